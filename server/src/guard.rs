//! Which requests the lab answers at all: those addressed to the machine itself. A page of
//! another site the user has open can reach a lab on 127.0.0.1 by DNS rebinding (its own name
//! made to resolve to 127.0.0.1: the browser then sends `Host: its.name:8080` and treats the
//! lab as that site, free to post JSON and read the answers), and can post a form to it from
//! its own origin. So a lab bound to the loopback address answers only requests whose `Host`
//! names the loopback (`localhost`, `127.0.0.1`, `[::1]`, any port) and whose `Origin`, when
//! the browser sends one, is such a host too; anything else is 403. A lab bound to another
//! address on purpose (`--host`) is reached by names the server cannot know, and checks
//! neither (the command line warns that anyone who reaches it can use it).

use crate::body::REQUEST;
use crate::error::ApiError;
use axum::extract::Request;
use axum::http::{HeaderMap, header};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

/// Which `Host` and `Origin` the lab answers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HostCheck {
    /// Only the loopback's names (the lab on 127.0.0.1, the default).
    #[default]
    Loopback,
    /// Any (a lab bound to another address on purpose).
    Any,
}

/// Whether `authority` (`host` or `host:port`) names the loopback.
fn loopback(authority: &str) -> bool {
    let host = match authority.strip_prefix('[') {
        // [::1]:8080
        Some(rest) => rest.split(']').next().unwrap_or(""),
        None => authority.rsplit_once(':').map_or(authority, |(h, _)| h),
    };
    host.eq_ignore_ascii_case("localhost")
        || host
            .parse::<std::net::IpAddr>()
            .is_ok_and(|ip| ip.is_loopback())
}

/// Why the request is refused, if it is: the header at fault and the reason.
pub fn refusal(check: HostCheck, headers: &HeaderMap) -> Option<(&'static str, String)> {
    if check == HostCheck::Any {
        return None;
    }
    // A request without a Host (HTTP/1.0, a test's) comes from no browser page.
    if let Some(host) = headers.get(header::HOST) {
        let host = host.to_str().unwrap_or("");
        if !loopback(host) {
            return Some((
                "host",
                format!(
                    "this lab answers requests to the loopback address only (localhost, \
                     127.0.0.1, [::1]), not to {host:?}: another name resolving here is how a \
                     page of another site would reach it"
                ),
            ));
        }
    }
    if let Some(origin) = headers.get(header::ORIGIN) {
        let origin = origin.to_str().unwrap_or("");
        let authority = origin
            .strip_prefix("http://")
            .or_else(|| origin.strip_prefix("https://"))
            .unwrap_or("");
        if !loopback(authority) {
            return Some((
                "origin",
                format!(
                    "a page of {origin:?} may not use this lab: only its own page (on the \
                     loopback address) does"
                ),
            ));
        }
    }
    None
}

/// The middleware: a refused request is answered 403 before any handler sees it.
pub async fn guard(check: HostCheck, req: Request, next: Next) -> Response {
    match refusal(check, req.headers()) {
        Some((key, reason)) => ApiError::new(403, REQUEST, key, reason).into_response(),
        None => next.run(req).await,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use axum::http::HeaderValue;

    fn headers(pairs: &[(header::HeaderName, &str)]) -> HeaderMap {
        let mut h = HeaderMap::new();
        for (k, v) in pairs {
            h.insert(k.clone(), HeaderValue::from_str(v).unwrap());
        }
        h
    }

    #[test]
    fn only_the_loopback_is_answered() {
        let ok = [
            "127.0.0.1:8080",
            "localhost:8080",
            "LOCALHOST",
            "[::1]:8080",
            "127.0.0.1",
            "127.1.2.3:9",
        ];
        for host in ok {
            let h = headers(&[(header::HOST, host)]);
            assert_eq!(refusal(HostCheck::Loopback, &h), None, "{host}");
        }
        for host in [
            "rebind.example:8080",
            "192.168.1.5:8080",
            "localhost.evil:80",
            "",
        ] {
            let h = headers(&[(header::HOST, host)]);
            assert_eq!(
                refusal(HostCheck::Loopback, &h).unwrap().0,
                "host",
                "{host}"
            );
            assert_eq!(refusal(HostCheck::Any, &h), None);
        }
        let page = headers(&[
            (header::HOST, "127.0.0.1:8080"),
            (header::ORIGIN, "http://127.0.0.1:8080"),
        ]);
        assert_eq!(refusal(HostCheck::Loopback, &page), None);
        for origin in ["http://evil.example", "null", "https://localhost.evil"] {
            let h = headers(&[(header::HOST, "127.0.0.1:8080"), (header::ORIGIN, origin)]);
            assert_eq!(
                refusal(HostCheck::Loopback, &h).unwrap().0,
                "origin",
                "{origin}"
            );
        }
        assert_eq!(refusal(HostCheck::Loopback, &HeaderMap::new()), None);
    }
}
