//! What one request may cost the server: the size of its body, the balls of its scene, the
//! simulated time and events of a shot, the planner's samples and routes, the heavy jobs run
//! at once and queued, and the wall time of each. Every limit is a value, so that a test or an
//! embedding program may choose its own; [`Limits::default`] is what `snooker serve` uses.

use std::time::Duration;

/// The bounds the server keeps every request within.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Largest request body, bytes (a full rack as JSON is about 3 kB).
    pub body_bytes: usize,
    /// Most balls in a scene (a snooker set is 22).
    pub balls: usize,
    /// Most events of one simulated shot: a scene asking for more is simulated with this cap.
    pub events: usize,
    /// Longest simulated time of one shot, s: a scene asking for more is simulated with this.
    pub sim_time: f64,
    /// Most points of the paths sent for one shot (the sample rate is lowered to fit; event
    /// instants are always sent).
    pub path_points: usize,
    /// Highest sample rate of the paths, Hz.
    pub path_rate: f64,
    /// Most ball samples of a recording to download (every ball at every instant; the
    /// break-off's is about 27,000 at 120 Hz): the rate is lowered to fit.
    pub recording_samples: usize,
    /// Most noise samples per planned shot.
    pub plan_samples: usize,
    /// Most alternative shots of a plan.
    pub plan_alternatives: usize,
    /// Smallest tolerance of a plan, m.
    pub plan_tolerance: f64,
    /// Largest search budget of the player per stroke, simulated shots.
    pub play_effort: u64,
    /// Most strokes of one visit of the player.
    pub play_strokes: usize,
    /// Heavy jobs (plans, the player thinking) run at once.
    pub heavy_jobs: usize,
    /// Heavy jobs waiting for a turn; more are refused (HTTP 503) until one ends.
    pub queued_jobs: usize,
    /// Wall time of one heavy job: past it the job is cancelled.
    pub job_time: Duration,
    /// Finished jobs kept for their results (the oldest are forgotten first).
    pub kept_jobs: usize,
    /// Bytes of the results (JSON text) of the finished jobs kept: past it the oldest are
    /// forgotten first (a plan's answer is about 0.1 MB, a stroke of the player's about
    /// 0.12 MB, a visit up to [`Limits::play_strokes`] of them).
    pub kept_bytes: usize,
    /// Light requests (simulate, referee, checks) computed at once; more wait their turn.
    pub light_jobs: usize,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            body_bytes: 256 * 1024,
            balls: 32,
            events: 20_000,
            sim_time: 600.0,
            path_points: 80_000,
            path_rate: 240.0,
            recording_samples: 60_000,
            plan_samples: 1024,
            plan_alternatives: 5,
            plan_tolerance: 1e-4,
            play_effort: 20_000,
            play_strokes: 60,
            heavy_jobs: 2,
            queued_jobs: 16,
            job_time: Duration::from_secs(120),
            kept_jobs: 64,
            kept_bytes: 32 * 1024 * 1024,
            light_jobs: 8,
        }
    }
}
