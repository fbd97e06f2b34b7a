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
        let mut de = serde_json::Deserializer::from_slice(&bytes);
        let value: T = serde_path_to_error::deserialize(&mut de).map_err(|e| {
            let key = e.path().to_string();
            let key = if key == "." || key == "?" { "" } else { &key };
            ApiError::bad(REQUEST, key, e.into_inner().to_string())
        })?;
        de.end()
            .map_err(|e| ApiError::bad(REQUEST, "", format!("not valid JSON: {e}")))?;
        Ok(Body(value))
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
