//! The shot lab: a local web server with one page and a small JSON API over the engine, scene,
//! planner, rules and player crates, so that a person can set up a position, strike, ask for
//! the shot, play a frame and play against the player. No physics here or in the page: every
//! number comes from those crates.
//!
//! - [`router`] is the whole application (an axum `Router`); [`serve`] runs it on a listener
//!   until a shutdown signal. The `snooker serve` command binds it to the loopback address.
//! - Requests are read by the scene and rules crates exactly as files are ([`input`]): bad
//!   input is HTTP 400 with `{file, key, reason, message}` ([`error`]), the message the
//!   command line prints. Everything a request may cost is bounded ([`limits`]).
//! - Long work (a plan, the player's visit) is a job ([`jobs`]) with progress and
//!   cancellation.
//! - The page ([`assets`]) is built into the binary and loads nothing from elsewhere.
//! - Only requests addressed to the loopback are answered ([`guard`]): no other site's page
//!   reaches the lab by DNS rebinding or a form.
//!
//! The API (JSON in and out; a scene is an object with the scene file's keys, a frame the
//! frame file's):
//!
//! | method and path | body | answer |
//! |---|---|---|
//! | `GET /api/info` | | the limits, the layouts, whether recordings can be made |
//! | `GET /api/layouts/{name}?reds=&seed=` | | a [`position::Position`] |
//! | `POST /api/scene/check` | `{scene}` | the position of the scene |
//! | `POST /api/scene/import` | `{toml, name?}` | the position of a scene or frame file's text |
//! | `POST /api/frame/check` | `{frame}` | the position of the frame |
//! | `POST /api/simulate` | `{scene, rate?}` | the result document and the paths ([`shot::ShotView`]) |
//! | `POST /api/download/scene` | `{scene}` | the scene file (TOML) |
//! | `POST /api/download/result` | `{scene}` | the JSON result, as `snooker simulate` writes it |
//! | `POST /api/download/recording` | `{scene, rate?}` | the Rerun recording (`.rrd`), its rate lowered to fit [`Limits::recording_samples`] |
//! | `POST /api/plan` | [`plan::PlanRequest`] | a job ([`jobs::JobStatus`]), 202 |
//! | `POST /api/frame/stroke` | `{frame, rate?}` | the referee's result, the paths, the next frame |
//! | `POST /api/play` | [`play::PlayRequest`] | a job (202): the player's visit, stroke by stroke |
//! | `GET /api/jobs/{id}?since=N` | | the job: state, shots so far, result; the parts from N |
//! | `POST /api/jobs/{id}/cancel` | | the job, cancelled |

pub mod assets;
pub mod body;
pub mod error;
pub mod guard;
pub mod input;
pub mod jobs;
pub mod limits;
pub mod paths;
pub mod plan;
pub mod play;
pub mod position;
pub mod record;
pub mod referee;
pub mod shot;
pub mod table;

pub use error::ApiError;
pub use limits::Limits;
pub use record::Recorder;

use axum::Json;
use axum::Router;
use axum::extract::rejection::PathRejection;
use axum::extract::{DefaultBodyLimit, Path, Query, State};
use axum::http::{HeaderValue, Method, StatusCode, Uri, header};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use body::Body;
use jobs::{JobStatus, Jobs};
use position::Position;
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::sync::Arc;
use tokio::sync::Semaphore;

/// What the server is built with.
#[derive(Clone, Default)]
pub struct Config {
    /// The bounds on every request.
    pub limits: Limits,
    /// Makes the recordings to download (none: the page offers none).
    pub recorder: Option<Arc<dyn Recorder>>,
    /// Which `Host` and `Origin` are answered ([`guard`]): the loopback's by default.
    pub hosts: guard::HostCheck,
}

/// The server's state, shared by the handlers.
struct Lab {
    limits: Limits,
    jobs: Arc<Jobs>,
    light: Semaphore,
    recorder: Option<Arc<dyn Recorder>>,
}

type Shared = State<Arc<Lab>>;

impl Lab {
    /// Runs light work (a simulation, a check) on a blocking thread, a few at a time.
    async fn light<T, F>(&self, work: F) -> Result<T, ApiError>
    where
        T: Send + 'static,
        F: FnOnce() -> Result<T, ApiError> + Send + 'static,
    {
        let _permit = self
            .light
            .acquire()
            .await
            .map_err(|e| ApiError::internal(e.to_string()))?;
        tokio::task::spawn_blocking(work)
            .await
            .map_err(|e| ApiError::internal(format!("the work stopped: {e}")))?
    }
}

/// The application: the page and the API, with `config`'s limits.
pub fn router(config: Config) -> Router {
    let lab = Arc::new(Lab {
        limits: config.limits,
        jobs: Arc::new(Jobs::new(config.limits)),
        light: Semaphore::new(config.limits.light_jobs.max(1)),
        recorder: config.recorder,
    });
    Router::new()
        .route("/api/info", get(info))
        .route("/api/layouts/{name}", get(layout))
        .route("/api/scene/check", post(scene_check))
        .route("/api/scene/import", post(scene_import))
        .route("/api/frame/check", post(frame_check))
        .route("/api/simulate", post(simulate))
        .route("/api/download/scene", post(download_scene))
        .route("/api/download/result", post(download_result))
        .route("/api/download/recording", post(download_recording))
        .route("/api/plan", post(plan))
        .route("/api/frame/stroke", post(frame_stroke))
        .route("/api/play", post(play))
        .route("/api/jobs/{id}", get(job))
        .route("/api/jobs/{id}/cancel", post(job_cancel))
        .method_not_allowed_fallback(method_not_allowed)
        .fallback(page)
        .layer(DefaultBodyLimit::max(config.limits.body_bytes))
        .layer(axum::middleware::from_fn(move |req, next| {
            body::declared_length(config.limits.body_bytes, req, next)
        }))
        .layer(axum::middleware::from_fn(move |req, next| {
            guard::guard(config.hosts, req, next)
        }))
        .with_state(lab)
}

/// Serves `app` on `listener` until `shutdown` completes.
pub async fn serve(
    listener: tokio::net::TcpListener,
    app: Router,
    shutdown: impl std::future::Future<Output = ()> + Send + 'static,
) -> std::io::Result<()> {
    axum::serve(listener, app)
        .with_graceful_shutdown(shutdown)
        .await
}

/// The page's files (GET); anything else that no route takes is an API error, as JSON.
async fn page(method: Method, uri: Uri) -> Response {
    let path = uri.path();
    if path == "/api" || path.starts_with("/api/") {
        return ApiError::not_found(format!("no endpoint {method} {path}")).into_response();
    }
    if method != Method::GET && method != Method::HEAD {
        return method_not_allowed(method, uri).await;
    }
    assets::asset(path)
}

/// A route asked with a method it does not take: 405, as JSON.
async fn method_not_allowed(method: Method, uri: Uri) -> Response {
    ApiError::new(
        405,
        body::REQUEST,
        "",
        format!("{} does not take {method}", uri.path()),
    )
    .into_response()
}

/// A job's id from the path: a bad one is 400 naming `id`, as JSON.
fn job_id(id: Result<Path<u64>, PathRejection>) -> Result<u64, ApiError> {
    id.map(|Path(id)| id)
        .map_err(|e| ApiError::bad(body::REQUEST, "id", e.body_text()))
}

/// `GET /api/info`.
#[derive(Serialize)]
struct Info {
    version: &'static str,
    layouts: Vec<position::LayoutInfo>,
    recordings: bool,
    player: bool,
    limits: LimitsView,
}

/// The limits a page may want to show.
#[derive(Serialize)]
struct LimitsView {
    balls: usize,
    plan_samples: usize,
    plan_alternatives: usize,
    play_effort: u64,
    play_effort_default: u64,
    play_strokes: usize,
    job_seconds: f64,
}

async fn info(State(lab): Shared) -> Json<Info> {
    Json(Info {
        version: env!("CARGO_PKG_VERSION"),
        layouts: position::layouts(),
        recordings: lab.recorder.is_some(),
        player: true,
        limits: LimitsView {
            balls: lab.limits.balls,
            plan_samples: lab.limits.plan_samples,
            plan_alternatives: lab.limits.plan_alternatives,
            play_effort: lab.limits.play_effort,
            play_effort_default: play::DEFAULT_EFFORT.min(lab.limits.play_effort),
            play_strokes: lab.limits.play_strokes,
            job_seconds: lab.limits.job_time.as_secs_f64(),
        },
    })
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LayoutQuery {
    #[serde(default)]
    reds: Option<String>,
    #[serde(default)]
    seed: Option<String>,
}

/// A query string that does not read: the key named (an unknown or repeated one).
fn query_error(e: axum::extract::rejection::QueryRejection) -> ApiError {
    let text = e.body_text();
    let reason = text
        .strip_prefix("Failed to deserialize query string: ")
        .unwrap_or(&text);
    ApiError::bad(body::REQUEST, &body::key_of("", reason), reason.to_string())
}

/// The whole number of query key `key`, if given: a bad one names its key.
fn whole<T: std::str::FromStr>(key: &str, v: Option<&str>) -> Result<Option<T>, ApiError> {
    v.map(|t| {
        t.parse().map_err(|_| {
            ApiError::bad(
                body::REQUEST,
                key,
                format!("a whole number (at least 0) is needed, got {t:?}"),
            )
        })
    })
    .transpose()
}

async fn layout(
    State(lab): Shared,
    name: Result<Path<String>, PathRejection>,
    query: Result<Query<LayoutQuery>, axum::extract::rejection::QueryRejection>,
) -> Result<Json<Position>, ApiError> {
    let Path(name) = name.map_err(|e| ApiError::bad(body::REQUEST, "name", e.body_text()))?;
    let Query(q) = query.map_err(query_error)?;
    let reds = whole::<usize>("reds", q.reds.as_deref())?;
    let seed = whole::<u64>("seed", q.seed.as_deref())?;
    let limits = lab.limits;
    lab.light(move || position::layout(&name, reds, seed, &limits))
        .await
        .map(Json)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneReq {
    scene: Value,
    #[serde(default)]
    rate: Option<f64>,
}

/// A scene alone: the checks and the scene and result downloads take no rate.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneOnly {
    scene: Value,
}

/// A frame alone (the frame check).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FrameOnly {
    frame: Value,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ImportReq {
    toml: String,
    #[serde(default)]
    name: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FrameReq {
    frame: Value,
    #[serde(default)]
    rate: Option<f64>,
}

async fn scene_check(
    State(lab): Shared,
    Body(req): Body<SceneOnly>,
) -> Result<Json<Position>, ApiError> {
    let limits = lab.limits;
    lab.light(move || position::of_scene(&input::scene(&req.scene, &limits)?))
        .await
        .map(Json)
}

/// A scene or frame file's text: read as a frame when it has a `[frame]` table.
async fn scene_import(
    State(lab): Shared,
    Body(req): Body<ImportReq>,
) -> Result<Json<Position>, ApiError> {
    let limits = lab.limits;
    lab.light(move || {
        let file = req.name.unwrap_or_else(|| "pasted.toml".into());
        let has_frame = toml::from_str::<toml::Table>(&req.toml)
            .map(|t| t.contains_key("frame"))
            .unwrap_or(false);
        if has_frame {
            position::of_frame_file(&input::frame_toml(&req.toml, &file, &limits)?)
        } else {
            position::of_scene(&input::scene_toml(&req.toml, &file, &limits)?)
        }
    })
    .await
    .map(Json)
}

async fn frame_check(
    State(lab): Shared,
    Body(req): Body<FrameOnly>,
) -> Result<Json<Position>, ApiError> {
    let limits = lab.limits;
    lab.light(move || position::of_frame_file(&input::frame(&req.frame, &limits)?))
        .await
        .map(Json)
}

async fn simulate(
    State(lab): Shared,
    Body(req): Body<SceneReq>,
) -> Result<Json<shot::ShotView>, ApiError> {
    let limits = lab.limits;
    lab.light(move || {
        let rate = shot::rate(req.rate, &limits)?;
        let checked = input::scene(&req.scene, &limits)?;
        let s = shot::simulate(&checked.scene, input::SCENE)?;
        Ok(shot::view(&checked.scene, &s, rate, &limits))
    })
    .await
    .map(Json)
}

/// A file to download: the scene's name, the file's extension and its type.
fn attachment(bytes: Vec<u8>, name: &str, ext: &str, kind: &'static str) -> Response {
    let mut r = bytes.into_response();
    let h = r.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static(kind));
    // A scene's name is free text of any length; the file's name keeps its first 100 safe
    // characters (a longer header is refused by common HTTP clients).
    let mut stem: String = name
        .chars()
        .filter(|c| c.is_ascii_alphanumeric() || "-_.".contains(*c))
        .take(100)
        .collect();
    // A name of no safe characters (日本語) gave ".toml", which browsers save as "toml".
    if stem.trim_matches('.').is_empty() {
        stem = "shot".to_string();
    }
    if let Ok(v) = HeaderValue::from_str(&format!("attachment; filename=\"{stem}.{ext}\"")) {
        h.insert(header::CONTENT_DISPOSITION, v);
    }
    r
}

async fn download_scene(
    State(lab): Shared,
    Body(req): Body<SceneOnly>,
) -> Result<Response, ApiError> {
    let limits = lab.limits;
    let (name, text) = lab
        .light(move || {
            let checked = input::scene(&req.scene, &limits)?;
            Ok((checked.scene.name.clone(), checked.file.to_toml()))
        })
        .await?;
    Ok(attachment(
        text.into_bytes(),
        &name,
        "toml",
        "application/toml",
    ))
}

async fn download_result(
    State(lab): Shared,
    Body(req): Body<SceneOnly>,
) -> Result<Response, ApiError> {
    let limits = lab.limits;
    let (name, text) = lab
        .light(move || {
            let checked = input::scene(&req.scene, &limits)?;
            Ok((
                checked.scene.name.clone(),
                shot::result_json(&checked, input::SCENE)?,
            ))
        })
        .await?;
    Ok(attachment(
        text.into_bytes(),
        &name,
        "json",
        "application/json",
    ))
}

async fn download_recording(
    State(lab): Shared,
    Body(req): Body<SceneReq>,
) -> Result<Response, ApiError> {
    let Some(recorder) = lab.recorder.clone() else {
        return Err(ApiError::not_found("this server makes no recordings"));
    };
    let limits = lab.limits;
    let (name, bytes) = lab
        .light(move || {
            // As `snooker simulate --record` samples (240 Hz) unless the request asks.
            let wanted = match req.rate {
                None => limits.path_rate,
                given => shot::rate(given, &limits)?,
            };
            let checked = input::scene(&req.scene, &limits)?;
            let s = shot::simulate(&checked.scene, input::SCENE)?;
            let rate = record::rate(&s, wanted, &limits)?;
            let bytes = recorder
                .shot(&checked.scene, &s, rate)
                .map_err(|e| ApiError::unfinished(input::SCENE, format!("the recording: {e}")))?;
            Ok((checked.scene.name.clone(), bytes))
        })
        .await?;
    Ok(attachment(bytes, &name, "rrd", "application/octet-stream"))
}

async fn plan(
    State(lab): Shared,
    Body(req): Body<plan::PlanRequest>,
) -> Result<(StatusCode, Json<JobStatus>), ApiError> {
    let limits = lab.limits;
    let checked = lab.light(move || plan::check(req, &limits)).await?;
    let job = lab.jobs.spawn("plan", move |job| plan::run(checked, job))?;
    Ok((StatusCode::ACCEPTED, Json(job.status())))
}

async fn play(
    State(lab): Shared,
    Body(req): Body<play::PlayRequest>,
) -> Result<(StatusCode, Json<JobStatus>), ApiError> {
    let limits = lab.limits;
    let checked = lab.light(move || play::check(req, &limits)).await?;
    let job = lab.jobs.spawn("play", move |job| play::run(checked, job))?;
    Ok((StatusCode::ACCEPTED, Json(job.status())))
}

async fn frame_stroke(
    State(lab): Shared,
    Body(req): Body<FrameReq>,
) -> Result<Json<referee::StrokeView>, ApiError> {
    let limits = lab.limits;
    lab.light(move || {
        let rate = shot::rate(req.rate, &limits)?;
        referee::stroke(&req.frame, rate, &limits)
    })
    .await
    .map(Json)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct JobQuery {
    #[serde(default)]
    since: Option<String>,
}

async fn job(
    State(lab): Shared,
    id: Result<Path<u64>, PathRejection>,
    query: Result<Query<JobQuery>, axum::extract::rejection::QueryRejection>,
) -> Result<Json<JobStatus>, ApiError> {
    let id = job_id(id)?;
    let Query(q) = query.map_err(query_error)?;
    let since = whole::<usize>("since", q.since.as_deref())?;
    let job = lab
        .jobs
        .get(id)
        .ok_or_else(|| ApiError::not_found(format!("no job {id}")))?;
    Ok(Json(job.status_since(since)))
}

async fn job_cancel(
    State(lab): Shared,
    id: Result<Path<u64>, PathRejection>,
) -> Result<Json<JobStatus>, ApiError> {
    let id = job_id(id)?;
    let job = lab
        .jobs
        .get(id)
        .ok_or_else(|| ApiError::not_found(format!("no job {id}")))?;
    job.cancel_with("cancelled on request");
    Ok(Json(job.status()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_download_always_has_a_file_name() {
        let name = |scene: &str| {
            let r = attachment(Vec::new(), scene, "toml", "application/toml");
            r.headers()[header::CONTENT_DISPOSITION]
                .to_str()
                .unwrap()
                .to_string()
        };
        assert_eq!(name("cut-30"), "attachment; filename=\"cut-30.toml\"");
        // No safe character: it was ".toml", saved by browsers as "toml".
        assert_eq!(name("日本語"), "attachment; filename=\"shot.toml\"");
        assert_eq!(name("..."), "attachment; filename=\"shot.toml\"");
        assert_eq!(name("a/b c"), "attachment; filename=\"abc.toml\"");
    }
}
