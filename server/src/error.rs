//! The API's one error: which input, which key, and why (the scene crate's [`SceneError`],
//! with the status the server answers with). Bad input is HTTP 400 with the key at fault; the
//! body is JSON: `{"file", "key", "reason", "message"}`, `message` being what the command line
//! prints for the same input after `error: `.

use axum::Json;
use axum::http::StatusCode;
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use snooker_scene::SceneError;

/// An error answered to a request.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ApiError {
    /// HTTP status: also in the body (an extension), so that a job's error says what it is
    /// (422 for a ball that cannot be potted, 500 for the server's own failure).
    pub status: u16,
    /// The input at fault (`scene`, `frame`, `request`), or empty.
    pub file: String,
    /// The key at fault, dotted (`balls[2].pos`, `pot`), or empty.
    pub key: String,
    /// Why.
    pub reason: String,
    /// The whole message, as the command line says it.
    pub message: String,
}

impl ApiError {
    /// An error of status `status`.
    pub fn new(status: u16, file: &str, key: &str, reason: impl Into<String>) -> ApiError {
        let e = SceneError::new(file, key, reason);
        ApiError::from_scene(status, e)
    }

    /// Bad input (400) at `key` of `file`.
    pub fn bad(file: &str, key: &str, reason: impl Into<String>) -> ApiError {
        ApiError::new(400, file, key, reason)
    }

    /// A scene or frame error, with status `status`.
    pub fn from_scene(status: u16, e: SceneError) -> ApiError {
        ApiError {
            status,
            // With no input at fault (a job not found, the server busy), the reason alone.
            message: if e.file.is_empty() && e.key.is_empty() {
                e.reason.clone()
            } else {
                e.to_string()
            },
            file: e.file,
            key: e.key,
            reason: e.reason,
        }
    }

    /// The server is busy (503): too many heavy jobs queued.
    pub fn busy(reason: impl Into<String>) -> ApiError {
        ApiError::new(503, "", "", reason)
    }

    /// No such thing (404).
    pub fn not_found(reason: impl Into<String>) -> ApiError {
        ApiError::new(404, "", "", reason)
    }

    /// A valid input whose computation could not finish (422): a shot still moving at the
    /// server's simulated-time limit, a ball that cannot be potted.
    pub fn unfinished(file: &str, reason: impl Into<String>) -> ApiError {
        ApiError::new(422, file, "", reason)
    }

    /// A failure of the server's own (500): never an answer to a valid input.
    pub fn internal(reason: impl Into<String>) -> ApiError {
        ApiError::new(500, "", "", format!("internal error: {}", reason.into()))
    }
}

impl From<SceneError> for ApiError {
    fn from(e: SceneError) -> ApiError {
        ApiError::from_scene(400, e)
    }
}

impl std::fmt::Display for ApiError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ApiError {}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let status = StatusCode::from_u16(self.status).unwrap_or(StatusCode::INTERNAL_SERVER_ERROR);
        (status, Json(self)).into_response()
    }
}
