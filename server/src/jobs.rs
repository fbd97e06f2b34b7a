//! Long work (a plan, the player thinking) as jobs: started at once with an id, run when one
//! of the server's few heavy slots is free (a semaphore), watched for progress (shots
//! simulated so far), cancelled on request or when it outlives its wall time (a [`Cancel`]
//! flag the planner checks before every shot), and kept a while for its result. A job may
//! report parts of its answer as it goes (the player's strokes, one by one): a poll asks for
//! the parts from the first it has not seen.
//!
//! Answers are kept as JSON text (a fraction of the memory of a JSON tree, written to each poll
//! as it is), and the finished jobs kept are bounded both in number and in the bytes of their
//! answers ([`Limits::kept_jobs`], [`Limits::kept_bytes`]): the oldest are forgotten first.

use crate::error::ApiError;
use crate::limits::Limits;
use serde::Serialize;
use serde_json::Value;
use serde_json::value::RawValue;
use snooker_planner::Cancel;
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::Instant;
use tokio::sync::{Notify, Semaphore};

/// Where a job's progress is read: shots simulated so far.
pub trait Progress: Send + Sync {
    /// Shots simulated so far.
    fn shots(&self) -> u64;
}

impl Progress for snooker_planner::Problem {
    fn shots(&self) -> u64 {
        snooker_planner::Problem::shots(self)
    }
}

impl Progress for snooker_player::Watch {
    fn shots(&self) -> u64 {
        snooker_player::Watch::shots(self)
    }
}

impl Progress for AtomicU64 {
    fn shots(&self) -> u64 {
        self.load(Ordering::Relaxed)
    }
}

/// Where a job is.
#[derive(Debug, Clone)]
enum State {
    Queued,
    Running,
    Done(Arc<RawValue>),
    Failed(ApiError),
    Cancelled(String),
}

/// One job.
pub struct Job {
    /// Its id.
    pub id: u64,
    /// What it does (`plan`, `play`).
    pub kind: &'static str,
    /// Its cancellation flag: the work checks it.
    pub cancel: Cancel,
    created: Instant,
    started: Mutex<Option<Instant>>,
    /// When it ended (done, failed or cancelled): its time running stops there.
    ended: Mutex<Option<Instant>>,
    state: Mutex<State>,
    progress: Mutex<Vec<Arc<dyn Progress>>>,
    done_shots: AtomicU64,
    note: Mutex<String>,
    cancel_reason: Mutex<Option<String>>,
    parts: Mutex<Vec<Arc<RawValue>>>,
    bytes: AtomicUsize,
    /// Wakes a job waiting for a slot when it is cancelled, so that it leaves the queue at
    /// once instead of when a slot frees.
    woken: Notify,
}

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

impl Job {
    /// Shots simulated so far by the work watched ([`Job::watch`]).
    pub fn shots(&self) -> u64 {
        self.done_shots.load(Ordering::Relaxed)
            + lock(&self.progress).iter().map(|p| p.shots()).sum::<u64>()
    }

    /// Counts the shots of `p` in the job's progress until [`Job::unwatch`].
    pub fn watch(&self, p: Arc<dyn Progress>) {
        lock(&self.progress).push(p);
    }

    /// Stops watching the progress sources, keeping their counts.
    pub fn unwatch(&self) {
        let mut list = lock(&self.progress);
        let n: u64 = list.iter().map(|p| p.shots()).sum();
        self.done_shots.fetch_add(n, Ordering::Relaxed);
        list.clear();
    }

    /// Reports a part of the answer (a stroke played), for the polls to come.
    pub fn report(&self, part: Value) -> Result<(), ApiError> {
        let raw = text(&part)?;
        lock(&self.parts).push(raw);
        Ok(())
    }

    /// Bytes of the answer and the parts kept (their JSON text).
    pub fn bytes(&self) -> usize {
        self.bytes.load(Ordering::Relaxed)
            + lock(&self.parts)
                .iter()
                .map(|p| p.get().len())
                .sum::<usize>()
    }

    /// A line saying what the job is doing now.
    pub fn set_note(&self, note: impl Into<String>) {
        *lock(&self.note) = note.into();
    }

    /// Cancels the job, saying why. A job still waiting for a slot is cancelled at once (and
    /// leaves the queue); a running one stops when its work sees the flag.
    pub fn cancel_with(&self, reason: &str) {
        let reason = {
            let mut r = lock(&self.cancel_reason);
            r.get_or_insert_with(|| reason.to_string()).clone()
        };
        self.cancel.cancel();
        {
            let mut state = lock(&self.state);
            if matches!(*state, State::Queued) {
                *state = State::Cancelled(reason);
                *lock(&self.ended) = Some(Instant::now());
            }
        }
        self.woken.notify_one();
    }

    /// Ends the job in `state` (done, failed or cancelled), its clock stopped.
    fn end(&self, state: State) {
        *lock(&self.ended) = Some(Instant::now());
        *lock(&self.state) = state;
    }

    fn finished(&self) -> bool {
        matches!(
            *lock(&self.state),
            State::Done(_) | State::Failed(_) | State::Cancelled(_)
        )
    }

    /// The job as the API reports it (no parts).
    pub fn status(&self) -> JobStatus {
        self.status_since(None)
    }

    /// The job as the API reports it, with the parts reported from number `since` (from 0) on
    /// when asked for.
    pub fn status_since(&self, since: Option<usize>) -> JobStatus {
        let state = lock(&self.state).clone();
        let started = *lock(&self.started);
        let ended = *lock(&self.ended);
        let running = matches!(state, State::Running);
        let (name, result, error, reason) = match state {
            State::Queued => ("queued", None, None, None),
            // A cancel asked of a running job shows at once; the job ends within a batch of
            // shots.
            State::Running => ("running", None, None, lock(&self.cancel_reason).clone()),
            State::Done(v) => ("done", Some(v), None, None),
            State::Failed(e) => ("failed", None, Some(e), None),
            State::Cancelled(r) => ("cancelled", None, None, Some(r)),
        };
        let (reported, parts) = {
            let all = lock(&self.parts);
            let parts = since.map(|k| all.get(k..).unwrap_or_default().to_vec());
            (all.len(), parts)
        };
        JobStatus {
            id: self.id,
            kind: self.kind,
            state: name,
            shots: self.shots(),
            // What it is doing: nothing once it has ended.
            note: if running {
                lock(&self.note).clone()
            } else {
                String::new()
            },
            waited: started
                .or(ended)
                .map_or(self.created.elapsed(), |s| s - self.created)
                .as_secs_f64(),
            elapsed: started.map_or(0.0, |s| {
                ended
                    .map_or(s.elapsed(), |e| e.saturating_duration_since(s))
                    .as_secs_f64()
            }),
            result,
            error,
            reason,
            reported,
            parts,
        }
    }
}

/// A job as the API reports it.
#[derive(Debug, Clone, Serialize)]
pub struct JobStatus {
    /// Its id.
    pub id: u64,
    /// What it does.
    pub kind: &'static str,
    /// `queued`, `running`, `done`, `failed` or `cancelled`.
    pub state: &'static str,
    /// Shots simulated so far.
    pub shots: u64,
    /// What it is doing now.
    pub note: String,
    /// Time spent waiting for a slot, s.
    pub waited: f64,
    /// Time running, s (to its end once it has ended).
    pub elapsed: f64,
    /// The answer, once done.
    #[serde(skip_serializing_if = "Option::is_none", serialize_with = "shared")]
    pub result: Option<Arc<RawValue>>,
    /// Why it failed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<ApiError>,
    /// Why it was cancelled (also while a running job is stopping after a cancel).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    /// Parts of the answer reported so far (strokes played).
    pub reported: usize,
    /// The parts from the one asked for (`?since=N`) on, when asked for.
    #[serde(
        skip_serializing_if = "Option::is_none",
        serialize_with = "shared_parts"
    )]
    pub parts: Option<Vec<Arc<RawValue>>>,
}

/// A kept result, written as the value it holds (shared, not copied, between polls).
fn shared<S: serde::Serializer>(v: &Option<Arc<RawValue>>, s: S) -> Result<S::Ok, S::Error> {
    v.as_deref().serialize(s)
}

/// `v` as JSON text, to keep.
fn text(v: &Value) -> Result<Arc<RawValue>, ApiError> {
    serde_json::value::to_raw_value(v)
        .map(Arc::from)
        .map_err(|e| ApiError::internal(format!("the answer as JSON: {e}")))
}

/// Kept parts, written as the values they hold.
fn shared_parts<S: serde::Serializer>(
    v: &Option<Vec<Arc<RawValue>>>,
    s: S,
) -> Result<S::Ok, S::Error> {
    match v {
        Some(parts) => s.collect_seq(parts.iter().map(|p| p.as_ref())),
        None => s.serialize_none(),
    }
}

/// The server's jobs.
pub struct Jobs {
    limits: Limits,
    next: AtomicU64,
    queued: AtomicUsize,
    heavy: Arc<Semaphore>,
    jobs: Mutex<BTreeMap<u64, Arc<Job>>>,
}

impl Jobs {
    /// No jobs yet; `limits` says how many run at once, wait, and are kept.
    pub fn new(limits: Limits) -> Jobs {
        Jobs {
            limits,
            next: AtomicU64::new(1),
            queued: AtomicUsize::new(0),
            heavy: Arc::new(Semaphore::new(limits.heavy_jobs.max(1))),
            jobs: Mutex::new(BTreeMap::new()),
        }
    }

    /// The job of this id, if kept.
    pub fn get(&self, id: u64) -> Option<Arc<Job>> {
        lock(&self.jobs).get(&id).cloned()
    }

    /// Jobs waiting for a slot.
    pub fn queued(&self) -> usize {
        self.queued.load(Ordering::Relaxed)
    }

    /// Starts `work` as a job of kind `kind` (on a blocking thread once a heavy slot is free);
    /// refused with 503 when the queue is full. Must be called within the Tokio runtime.
    pub fn spawn<F>(self: &Arc<Self>, kind: &'static str, work: F) -> Result<Arc<Job>, ApiError>
    where
        F: FnOnce(&Job) -> Result<Value, ApiError> + Send + 'static,
    {
        let waiting = self.queued.fetch_add(1, Ordering::SeqCst);
        if waiting >= self.limits.queued_jobs {
            self.queued.fetch_sub(1, Ordering::SeqCst);
            return Err(ApiError::busy(format!(
                "{waiting} jobs are waiting already (at most {}): try again when one ends",
                self.limits.queued_jobs
            )));
        }
        let job = Arc::new(Job {
            id: self.next.fetch_add(1, Ordering::Relaxed),
            kind,
            cancel: Cancel::new(),
            created: Instant::now(),
            started: Mutex::new(None),
            ended: Mutex::new(None),
            state: Mutex::new(State::Queued),
            progress: Mutex::new(Vec::new()),
            done_shots: AtomicU64::new(0),
            note: Mutex::new(String::new()),
            cancel_reason: Mutex::new(None),
            parts: Mutex::new(Vec::new()),
            bytes: AtomicUsize::new(0),
            woken: Notify::new(),
        });
        self.keep(job.clone());
        let jobs = self.clone();
        let run = job.clone();
        tokio::spawn(async move {
            // Wait for a slot, or leave the queue as soon as the job is cancelled.
            let permit = tokio::select! {
                p = jobs.heavy.clone().acquire_owned() => Some(p),
                () = run.woken.notified() => None,
            };
            jobs.queued.fetch_sub(1, Ordering::SeqCst);
            let slot = match permit {
                Some(Ok(p)) => Some(p),
                Some(Err(_)) => {
                    run.end(State::Failed(ApiError::internal("the job slots closed")));
                    return;
                }
                None => None,
            };
            if slot.is_none() || run.cancel.is_cancelled() {
                let reason = lock(&run.cancel_reason).clone().unwrap_or_default();
                run.end(State::Cancelled(reason));
                return;
            }
            *lock(&run.started) = Some(Instant::now());
            *lock(&run.state) = State::Running;
            let watchdog = {
                let job = run.clone();
                let limit = jobs.limits.job_time;
                tokio::spawn(async move {
                    tokio::time::sleep(limit).await;
                    job.cancel_with(&format!(
                        "stopped at the server's wall-time limit of {} s",
                        limit.as_secs_f64()
                    ));
                })
            };
            let worker = run.clone();
            let out = tokio::task::spawn_blocking(move || work(&worker)).await;
            watchdog.abort();
            run.unwatch();
            let state = if run.cancel.is_cancelled() {
                State::Cancelled(lock(&run.cancel_reason).clone().unwrap_or_default())
            } else {
                match out.map(|r| r.and_then(|v| text(&v))) {
                    Ok(Ok(v)) => {
                        run.bytes.store(v.get().len(), Ordering::Relaxed);
                        State::Done(v)
                    }
                    Ok(Err(e)) => State::Failed(e),
                    Err(e) => State::Failed(ApiError::internal(format!("the job stopped: {e}"))),
                }
            };
            run.end(state);
        });
        Ok(job)
    }

    /// Keeps `job`, forgetting the oldest finished jobs beyond the limits: more than
    /// [`Limits::kept_jobs`] of them, or answers of more than [`Limits::kept_bytes`] in all.
    fn keep(&self, job: Arc<Job>) {
        let mut jobs = lock(&self.jobs);
        jobs.insert(job.id, job);
        // Newest first: keep while both limits allow, forget the rest.
        let finished: Vec<(u64, usize)> = jobs
            .iter()
            .rev()
            .filter(|(_, j)| j.finished())
            .map(|(id, j)| (*id, j.bytes()))
            .collect();
        let mut bytes = 0;
        for (k, (id, b)) in finished.into_iter().enumerate() {
            bytes += b;
            if k >= self.limits.kept_jobs || bytes > self.limits.kept_bytes {
                jobs.remove(&id);
            }
        }
    }

    /// Jobs kept (finished or not) and the bytes of their answers.
    pub fn kept(&self) -> (usize, usize) {
        let jobs = lock(&self.jobs);
        (jobs.len(), jobs.values().map(|j| j.bytes()).sum())
    }
}
