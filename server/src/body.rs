//! Request bodies: JSON read into the request's typed struct, an error naming the key at
//! fault (the request's own keys: `pot`, `target`, `scene`), and a body over the server's size
//! limit refused (413) before it is read whole.

use crate::error::ApiError;
use axum::body::Bytes;
use axum::extract::{FromRequest, Request};
use serde::de::DeserializeOwned;

/// The name the API's errors give a request's own keys.
pub const REQUEST: &str = "request";

/// A JSON body read as `T`.
pub struct Body<T>(pub T);

impl<S: Send + Sync, T: DeserializeOwned> FromRequest<S> for Body<T> {
    type Rejection = ApiError;

    async fn from_request(req: Request, state: &S) -> Result<Self, Self::Rejection> {
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
