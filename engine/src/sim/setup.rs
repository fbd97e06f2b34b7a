//! What a shot starts from ([`Setup`]) and its checks: parameters in range, finite and bounded
//! starting states, unique ids, every ball on the cloth and clear of the cushions, no two balls
//! overlapping.

use crate::ball::Ball;
use crate::detect;
use crate::impact::Models;
use crate::motion;
use crate::params::Params;
use crate::shown::Shown;
use crate::table::Table;
use serde::{Deserialize, Serialize};

/// Fastest a ball may move at the start of a shot, m/s: above anything a cue gives (a cue at
/// its fastest, [`crate::cue::MAX_CUE_SPEED`], gives a ball less than twice its speed).
pub const MAX_BALL_SPEED: f64 = 30.0;
/// Largest spin a ball may have at the start of a shot, as the speed R |w| of its surface, m/s:
/// above anything a cue gives (at most 5/2 of the ball's speed).
pub const MAX_SPIN_SPEED: f64 = 100.0;

/// Limits of one simulation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SimOptions {
    /// Most events a shot may have before it is stopped with an error.
    pub max_events: usize,
    /// Most events at one and the same instant before the shot is stopped with an error; a
    /// shot of n balls is allowed n^3 if that is more ([`SimOptions::events_at_instant_cap`]).
    pub max_events_at_instant: usize,
    /// Simulated time within which every ball must come to rest, s.
    pub max_time: f64,
    /// Stop (without error) at this time even if balls still move.
    pub horizon: Option<f64>,
}

impl Default for SimOptions {
    fn default() -> Self {
        SimOptions {
            // Above a physical micro-collision train's count: a struck ball slides at most
            // about 14 s (R|w| <= 100 m/s, thesis cloth), at most 2,060 micro-collisions per
            // pair per second (physics.md); a pressed chain of a dozen pairs makes some
            // 350,000. 100,000 stopped such valid shots as runaways (stop 42).
            max_events: 1_000_000,
            max_events_at_instant: 10_000,
            max_time: 3600.0,
            horizon: None,
        }
    }
}

impl SimOptions {
    /// Checks the limits: at least one event, `max_time` a positive finite number of seconds,
    /// a horizon (if any) finite and not negative. A NaN horizon would be passed by every
    /// comparison and silently mean none; a NaN `max_time` would never stop a shot.
    pub fn validate(&self) -> Result<(), SetupError> {
        let bad = |field: &str, reason: String| {
            Err(SetupError {
                ball: None,
                field: format!("options.{field}"),
                reason,
            })
        };
        if self.max_events == 0 {
            return bad("max_events", "must be at least 1".into());
        }
        if !(self.max_time.is_finite() && self.max_time > 0.0) {
            return bad(
                "max_time",
                format!(
                    "must be a positive finite number of seconds, got {}",
                    Shown(self.max_time)
                ),
            );
        }
        if let Some(h) = self.horizon
            && !(h.is_finite() && h >= 0.0)
        {
            return bad(
                "horizon",
                format!(
                    "must be a finite number of seconds, not negative, got {}",
                    Shown(h)
                ),
            );
        }
        Ok(())
    }

    /// The most events allowed at one instant in a shot of `balls` balls: the larger of
    /// [`SimOptions::max_events_at_instant`] and `balls`^3. Same-instant impacts are resolved
    /// one pair at a time (the sequential hypothesis), and a line of n touching balls struck
    /// end on (a Newton's cradle) takes about n^3 / 20 of them before no touching pair
    /// approaches (measured: 12,768 for 60 balls, 82,340 for 120), each leaving its pair
    /// separating at [`crate::impact::MIN_SEPARATION`] at least.
    pub fn events_at_instant_cap(&self, balls: usize) -> usize {
        let cube = balls.saturating_mul(balls).saturating_mul(balls);
        self.max_events_at_instant.max(cube)
    }
}

/// Everything a shot starts from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Setup {
    /// The table.
    pub table: Table,
    /// Physical parameters.
    pub params: Params,
    /// Impact models.
    pub models: Models,
    /// The balls with their starting states.
    pub balls: Vec<Ball>,
}

/// A setup that cannot be simulated.
#[derive(Clone, Debug, PartialEq)]
pub struct SetupError {
    /// Index of the ball at fault, if one is.
    pub ball: Option<usize>,
    /// The field at fault ("pos", "vel", "spin", "id", or a parameter name).
    pub field: String,
    /// Why.
    pub reason: String,
}

impl std::fmt::Display for SetupError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.ball {
            Some(i) => write!(f, "balls[{i}].{}: {}", self.field, self.reason),
            None => write!(f, "{}: {}", self.field, self.reason),
        }
    }
}

impl std::error::Error for SetupError {}

/// Why ball `b` (radius `r`) cannot start with its velocity and spin, if it cannot: the field
/// at fault ("vel" or "spin") and the reason. A speed above [`MAX_BALL_SPEED`] or a spin whose
/// surface speed is above [`MAX_SPIN_SPEED`] is beyond any shot. [`Setup::validate`] checks
/// it for every ball; a scene checks it for a ball before striking it, so that a ball's own
/// motion is not blamed on the cue.
pub fn motion_error(b: &Ball, r: f64) -> Option<(&'static str, String)> {
    let speed = b.state.vel.norm();
    if speed > MAX_BALL_SPEED {
        return Some((
            "vel",
            format!(
                "ball \"{}\": a speed of {speed} m/s is beyond any shot (at most \
                 {MAX_BALL_SPEED} m/s)",
                b.id
            ),
        ));
    }
    let surface = b.state.spin.norm() * r;
    if surface > MAX_SPIN_SPEED {
        return Some((
            "spin",
            format!(
                "ball \"{}\": a spin of {} rad/s (surface speed R|w| = {surface} m/s) is \
                 beyond any shot (R|w| at most {MAX_SPIN_SPEED} m/s)",
                b.id,
                b.state.spin.norm()
            ),
        ));
    }
    None
}

impl Setup {
    /// Checks parameters, the table's geometry ([`Table::geometry_error`]) and the starting
    /// positions: finite numbers, unique ids, every ball on the cloth and clear of the
    /// cushions, no two balls overlapping (touching is allowed).
    pub fn validate(&self) -> Result<(), SetupError> {
        self.params.validate().map_err(|e| SetupError {
            ball: None,
            field: format!("params.{}", e.name),
            reason: e.reason,
        })?;
        if let Some((field, reason)) = self.table.geometry_error() {
            return Err(SetupError {
                ball: None,
                field: format!("table.{field}"),
                reason,
            });
        }
        let p = &self.params;
        let r = p.ball_radius;
        let contact = p.cushion_contact_distance();
        for (i, b) in self.balls.iter().enumerate() {
            let bad = |field: &str, reason: String| SetupError {
                ball: Some(i),
                field: field.into(),
                reason,
            };
            for (field, v) in [
                ("pos", b.state.pos),
                ("vel", b.state.vel),
                ("spin", b.state.spin),
            ] {
                if !v.iter().all(|x| x.is_finite()) {
                    return Err(bad(
                        field,
                        format!("ball \"{}\": values must be finite", b.id),
                    ));
                }
            }
            if let Some((field, reason)) = motion_error(b, r) {
                return Err(bad(field, reason));
            }
            if self.balls[..i].iter().any(|o| o.id == b.id) {
                return Err(bad("id", format!("ball id \"{}\" is used twice", b.id)));
            }
            if b.state.pos.z < r - detect::TOUCH_TOL {
                return Err(bad("pos", format!("ball \"{}\" is below the cloth", b.id)));
            }
            if b.state.pos.z <= r + motion::ON_CLOTH && b.state.vel.z < 0.0 {
                return Err(bad(
                    "vel",
                    format!("ball \"{}\" is on the cloth and moving down into it", b.id),
                ));
            }
            if let Some(why) = self
                .table
                .placement_error(b.state.pos.xy().push(0.0), contact)
            {
                return Err(bad("pos", format!("ball \"{}\": {why}", b.id)));
            }
            for o in &self.balls[..i] {
                let gap = (b.state.pos - o.state.pos).norm() - 2.0 * r;
                if gap < -detect::TOUCH_TOL {
                    return Err(bad(
                        "pos",
                        format!(
                            "ball \"{}\" overlaps ball \"{}\" by {:.3} mm",
                            b.id,
                            o.id,
                            -gap * 1e3
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}
