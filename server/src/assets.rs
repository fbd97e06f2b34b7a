//! The page and its assets, built into the binary: plain JavaScript modules, one style sheet,
//! an icon; nothing fetched from anywhere else, so the page works offline.

use axum::http::{HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};

/// The files served: path, content type, bytes.
const FILES: [(&str, &str, &str); 10] = [
    (
        "/",
        "text/html; charset=utf-8",
        include_str!("../web/index.html"),
    ),
    (
        "/style.css",
        "text/css; charset=utf-8",
        include_str!("../web/style.css"),
    ),
    (
        "/app.js",
        "text/javascript; charset=utf-8",
        include_str!("../web/app.js"),
    ),
    (
        "/api.js",
        "text/javascript; charset=utf-8",
        include_str!("../web/api.js"),
    ),
    (
        "/table.js",
        "text/javascript; charset=utf-8",
        include_str!("../web/table.js"),
    ),
    (
        "/strike.js",
        "text/javascript; charset=utf-8",
        include_str!("../web/strike.js"),
    ),
    (
        "/plan.js",
        "text/javascript; charset=utf-8",
        include_str!("../web/plan.js"),
    ),
    (
        "/play.js",
        "text/javascript; charset=utf-8",
        include_str!("../web/play.js"),
    ),
    (
        "/player.js",
        "text/javascript; charset=utf-8",
        include_str!("../web/player.js"),
    ),
    (
        "/favicon.svg",
        "image/svg+xml",
        include_str!("../web/favicon.svg"),
    ),
];

/// The asset at `path`, or 404.
pub fn asset(path: &str) -> Response {
    let path = if path == "/index.html" { "/" } else { path };
    let path = if path == "/favicon.ico" {
        "/favicon.svg"
    } else {
        path
    };
    match FILES.iter().find(|(p, _, _)| *p == path) {
        Some((_, kind, body)) => {
            let mut r = (*body).into_response();
            let h = r.headers_mut();
            h.insert(header::CONTENT_TYPE, HeaderValue::from_static(kind));
            h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
            // The page loads nothing from elsewhere; the browser is told so too.
            h.insert(
                header::CONTENT_SECURITY_POLICY,
                HeaderValue::from_static(
                    "default-src 'self'; img-src 'self' blob: data:; style-src 'self' 'unsafe-inline'; connect-src 'self'",
                ),
            );
            r
        }
        None => (StatusCode::NOT_FOUND, "not found").into_response(),
    }
}

/// Every asset path (for the tests).
pub fn paths() -> impl Iterator<Item = &'static str> {
    FILES.iter().map(|(p, _, _)| *p)
}
