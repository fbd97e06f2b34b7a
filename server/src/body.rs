//! Request bodies: JSON read into the request's typed struct, an error naming the key at
//! fault (the request's own keys: `pot`, `target`, `scene`), and a body over the server's size
//! limit refused (413) before it is read whole. A body must be sent as `application/json`:
//! a page of another origin can post only the "simple" types (form data, `text/plain`) without
//! the browser asking the lab first (a CORS preflight, which the lab does not grant), so this
//! keeps other sites the user visits from starting work on a lab running on their machine.

use crate::error::ApiError;
use axum::body::Bytes;
use axum::extract::{FromRequest, Request};
use axum::http::header;
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};
use serde::de::DeserializeOwned;

/// The name the API's errors give a request's own keys.
pub const REQUEST: &str = "request";

/// A JSON body read as `T`.
pub struct Body<T>(pub T);

impl<S: Send + Sync, T: DeserializeOwned> FromRequest<S> for Body<T> {
    type Rejection = ApiError;

    async fn from_request(req: Request, state: &S) -> Result<Self, Self::Rejection> {
        let kind = req
            .headers()
            .get(header::CONTENT_TYPE)
            .and_then(|v| v.to_str().ok())
            .unwrap_or("");
        if !is_json(kind) {
            return Err(ApiError::new(
                415,
                REQUEST,
                "",
                format!(
                    "the body must be sent as content-type: application/json (got {:?}); \
                     other types are refused so that pages of other sites cannot start work here",
                    kind
                ),
            ));
        }
        let bytes = Bytes::from_request(req, state).await.map_err(|e| {
            let status = e.status().as_u16();
            ApiError::new(status, REQUEST, "", e.body_text())
        })?;
        // A request is an object of named keys: an array would be read by position (nested
        // objects are refused as arrays by `Tables`; the top level gets its own message).
        let first = bytes.iter().find(|b| !b.is_ascii_whitespace());
        if first.is_some_and(|&b| b != b'{') {
            return Err(ApiError::bad(
                REQUEST,
                "",
                "the body must be a JSON object of the request's keys",
            ));
        }
        let mut de = serde_json::Deserializer::from_slice(&bytes);
        let value: T = serde_path_to_error::deserialize(snooker_scene::tables::Tables(&mut de))
            .map_err(|e| {
                let path = e.path().to_string();
                let reason = e.into_inner().to_string();
                ApiError::bad(REQUEST, &key_of(&path, &reason), reason)
            })?;
        de.end()
            .map_err(|e| ApiError::bad(REQUEST, "", format!("not valid JSON: {e}")))?;
        Ok(Body(value))
    }
}

/// Refuses (413) a request whose declared `content-length` is over `limit` bytes at once: the
/// body limit alone answered only once that much had been sent (a client declaring 1 GB and
/// sending slowly waited for its answer).
pub async fn declared_length(limit: usize, req: axum::extract::Request, next: Next) -> Response {
    let declared = req
        .headers()
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.trim().parse::<u64>().ok());
    match declared {
        Some(n) if n > limit as u64 => ApiError::new(
            413,
            REQUEST,
            "",
            format!("a body of {n} bytes is over the server's limit of {limit}"),
        )
        .into_response(),
        _ => next.run(req).await,
    }
}

/// The dotted key a serde error is about: its path, and for a missing, unknown or duplicate
/// field the field itself (`pot`, not the request's top level).
pub fn key_of(path: &str, reason: &str) -> String {
    let path = if path == "." || path == "?" { "" } else { path };
    let field = ["missing field `", "unknown field `", "duplicate field `"]
        .iter()
        .find_map(|p| reason.find(p).map(|i| &reason[i + p.len()..]))
        .and_then(|r| r.split('`').next());
    match (path, field) {
        ("", Some(f)) => f.to_string(),
        (p, Some(f)) if !p.ends_with(f) => format!("{p}.{f}"),
        (p, _) => p.to_string(),
    }
}

/// Whether a `content-type` value is JSON's (`application/json`, any parameters after `;`).
fn is_json(kind: &str) -> bool {
    let essence = kind.split(';').next().unwrap_or("").trim();
    essence.eq_ignore_ascii_case("application/json")
}

#[cfg(test)]
mod tests {
    use super::is_json;

    #[test]
    fn only_json_content_types_are_json() {
        assert!(is_json("application/json"));
        assert!(is_json("Application/JSON; charset=utf-8"));
        assert!(!is_json(""));
        assert!(!is_json("text/plain"));
        assert!(!is_json("application/x-www-form-urlencoded"));
        assert!(!is_json("multipart/form-data; boundary=x"));
        assert!(!is_json("application/jsonp"));
    }
}
