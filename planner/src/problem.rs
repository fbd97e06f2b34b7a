//! What is asked of the planner (the ball to pot, the pocket, the cue ball's target, the
//! limits of the search, the execution noise), checked against the scene once, up front.

use snooker_engine::cue::{MAX_CUE_SPEED, MAX_ELEVATION};
use snooker_engine::{Params, Setup, SimOptions, Vec3};
use snooker_scene::Scene;
use std::sync::atomic::{AtomicU64, Ordering};

/// Why there is no plan.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanError {
    /// The request does not make sense for this scene (exit 2 in the command).
    #[error("{key}: {reason}")]
    BadInput {
        /// The option or key at fault (`--pot`, `--bounds speed`, ...).
        key: String,
        /// Why.
        reason: String,
    },
    /// No strike within the bounds pots the ball (exit 1 in the command).
    #[error("{0}")]
    CannotPot(String),
}

fn bad(key: &str, reason: impl Into<String>) -> PlanError {
    PlanError::BadInput {
        key: key.into(),
        reason: reason.into(),
    }
}

/// A closed interval of one strike variable.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Interval {
    /// Least value.
    pub lo: f64,
    /// Greatest value.
    pub hi: f64,
}

impl Interval {
    /// The point a fraction `u` (0..1, clamped) of the way from `lo` to `hi`.
    pub fn at(&self, u: f64) -> f64 {
        self.lo + u.clamp(0.0, 1.0) * (self.hi - self.lo)
    }

    /// True when the interval is a single value (that variable is not searched).
    pub fn is_fixed(&self) -> bool {
        self.hi <= self.lo
    }
}

/// Where the search may go: cue speed (m/s), elevation (rad), and the tip's offsets from the
/// ball's centre across the cue (side, m, + to the right) and up it (height, m, + above).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Bounds {
    /// Cue speed, m/s.
    pub speed: Interval,
    /// Cue elevation, rad.
    pub elevation: Interval,
    /// Side offset, m.
    pub side: Interval,
    /// Height offset, m.
    pub height: Interval,
}

impl Bounds {
    /// The default search: 0.3 to 6 m/s (a slow roll to a firm pot), a level cue, and offsets
    /// up to 0.8 of the miscue limit each way (thesis eq. 7.7).
    pub fn default_for(p: &Params) -> Bounds {
        let reach = 0.8 * p.miscue_limit * p.ball_radius;
        Bounds {
            speed: Interval { lo: 0.3, hi: 6.0 },
            elevation: Interval { lo: 0.0, hi: 0.0 },
            side: Interval {
                lo: -reach,
                hi: reach,
            },
            height: Interval {
                lo: -reach,
                hi: reach,
            },
        }
    }

    /// `self` with the intervals of `spec` ("speed=0.3..6,elevation=0..0,side=-0.01..0.01,
    /// height=..."), each checked against the engine's strike limits: the cue's speed and
    /// elevation ranges, and offsets at which the cue's axis passes within the miscue limit of
    /// the centre (`cue.rs`: the contact lies miscue_limit R from the axis when the axis
    /// passes miscue_limit (R + r) from the centre; a height offset is foreshortened by
    /// cos(elevation), so a steeper cue allows a larger one).
    pub fn with_spec(mut self, spec: &str, p: &Params) -> Result<Bounds, PlanError> {
        // Offsets are checked once the elevations are known, whatever the order given.
        let mut offsets: Vec<(String, &str, Interval)> = Vec::new();
        for part in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let key = format!("--bounds {part}");
            let (name, range) = part
                .split_once('=')
                .ok_or_else(|| bad(&key, "expected NAME=LO..HI"))?;
            let (lo, hi) = range
                .split_once("..")
                .ok_or_else(|| bad(&key, "expected NAME=LO..HI"))?;
            let num = |s: &str| {
                s.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| bad(&key, format!("`{s}` is not a finite number")))
            };
            let iv = Interval {
                lo: num(lo)?,
                hi: num(hi)?,
            };
            if iv.lo > iv.hi {
                return Err(bad(&key, "the low end is above the high end"));
            }
            let (slot, allowed, unit) = match name.trim() {
                "speed" => (&mut self.speed, (1e-3, MAX_CUE_SPEED), "m/s"),
                "elevation" => (&mut self.elevation, (0.0, MAX_ELEVATION), "rad"),
                "side" => {
                    offsets.push((key, "side", iv));
                    continue;
                }
                "height" => {
                    offsets.push((key, "height", iv));
                    continue;
                }
                other => {
                    return Err(bad(
                        &key,
                        format!("unknown variable `{other}` (speed, elevation, side, height)"),
                    ));
                }
            };
            if iv.lo < allowed.0 || iv.hi > allowed.1 {
                return Err(bad(
                    &key,
                    format!(
                        "outside the engine's strike limits [{}, {}] {unit}",
                        allowed.0, allowed.1
                    ),
                ));
            }
            *slot = iv;
        }
        let reach = p.miscue_limit * (p.ball_radius + p.cue_tip_radius);
        for (key, name, iv) in offsets {
            let (limit, slot) = if name == "side" {
                (reach, &mut self.side)
            } else {
                (reach / self.elevation.hi.cos(), &mut self.height)
            };
            if iv.lo < -limit || iv.hi > limit {
                return Err(bad(
                    &key,
                    format!(
                        "outside the engine's strike limits [{:.4}, {limit:.4}] m: beyond, the \
                         cue's axis passes more than miscue_limit (R + r) = {:.1} mm from the \
                         centre at every elevation up to {:.4} rad, a miscue",
                        -limit,
                        reach * 1e3,
                        self.elevation.hi
                    ),
                ));
            }
            *slot = iv;
        }
        Ok(self)
    }
}

/// How far a strike may stray from the one intended: independent normal errors with these
/// standard deviations. Default: the command's example, a steady player's cue (a robot's is
/// a matter of measurement: thesis §7.1.3).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Noise {
    /// Heading, rad.
    pub aim: f64,
    /// Speed, as a fraction of the speed (0.02 = 2 %).
    pub speed: f64,
    /// Each tip offset, m.
    pub offset: f64,
}

impl Default for Noise {
    fn default() -> Noise {
        Noise {
            aim: 0.002,
            speed: 0.02,
            offset: 0.001,
        }
    }
}

impl Noise {
    /// `self` with the values of `spec` ("aim=0.002,speed=0.02,offset=0.001").
    pub fn with_spec(mut self, spec: &str) -> Result<Noise, PlanError> {
        for part in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            let key = format!("--noise {part}");
            let (name, value) = part
                .split_once('=')
                .ok_or_else(|| bad(&key, "expected NAME=VALUE"))?;
            let v: f64 = value
                .trim()
                .parse()
                .ok()
                .filter(|v: &f64| v.is_finite() && *v >= 0.0)
                .ok_or_else(|| bad(&key, "expected a finite number >= 0"))?;
            match name.trim() {
                "aim" => self.aim = v,
                "speed" => self.speed = v,
                "offset" => self.offset = v,
                other => {
                    return Err(bad(
                        &key,
                        format!("unknown noise `{other}` (aim, speed, offset)"),
                    ));
                }
            }
        }
        Ok(self)
    }
}

/// A planning request, by name (as the command takes it).
#[derive(Debug, Clone)]
pub struct Request {
    /// Id of the cue ball (the ball struck).
    pub cue_ball: String,
    /// Id of the object ball to pot.
    pub pot: String,
    /// Name of the pocket (`top-left`, `middle-left`, ... as in the result's `pocket`).
    pub pocket: String,
    /// Where the cue ball should stop (x, y), m.
    pub target: [f64; 2],
    /// Distance to the target that counts as reached, m.
    pub tolerance: f64,
    /// The search's limits.
    pub bounds: Bounds,
    /// Execution noise.
    pub noise: Noise,
    /// Monte Carlo samples per shot for its robustness.
    pub samples: usize,
    /// Most alternative shots to return.
    pub alternatives: usize,
    /// Seed of the noise samples.
    pub seed: u64,
}

impl Request {
    /// A request with the default bounds (for `p`), noise, 256 samples, 3 alternatives and
    /// a 1 mm tolerance.
    pub fn new(pot: &str, pocket: &str, target: [f64; 2], p: &Params) -> Request {
        Request {
            cue_ball: "cue".into(),
            pot: pot.into(),
            pocket: pocket.into(),
            target,
            tolerance: 1e-3,
            bounds: Bounds::default_for(p),
            noise: Noise::default(),
            samples: 256,
            alternatives: 3,
            seed: 1,
        }
    }
}

/// A checked request on a scene: indices resolved, the cue ball as it lies (any strike in the
/// scene undone), and a count of the shots simulated.
#[derive(Debug)]
pub struct Problem {
    /// The position, the cue ball at rest where it lies.
    pub setup: Setup,
    /// The scene's simulation limits (as `snooker simulate` uses them).
    pub options: SimOptions,
    /// The request.
    pub request: Request,
    /// Index of the cue ball.
    pub cue: usize,
    /// Index of the object ball.
    pub object: usize,
    /// Index of the pocket in the table's pockets.
    pub pocket: usize,
    /// The cue ball's target, m (z = R).
    pub target: Vec3,
    shots: AtomicU64,
}

impl Problem {
    /// Checks `request` against `scene`.
    pub fn new(scene: &Scene, request: Request) -> Result<Problem, PlanError> {
        let mut setup = scene.setup.clone();
        if let Some(s) = &scene.strike {
            // The scene's own strike is ignored: the cue ball lies where it was before it.
            setup.balls[s.index].state = s.before;
        }
        let p = setup.params;
        let r = p.ball_radius;
        let index = |key: &str, id: &str| {
            setup.balls.iter().position(|b| b.id == id).ok_or_else(|| {
                let ids: Vec<&str> = setup.balls.iter().map(|b| b.id.as_str()).collect();
                bad(
                    key,
                    format!("no ball \"{id}\" in the scene (it has {})", ids.join(", ")),
                )
            })
        };
        let cue = index("--cue-ball", &request.cue_ball)?;
        let object = index("--pot", &request.pot)?;
        if object == cue {
            return Err(bad("--pot", "the cue ball cannot be the ball to pot"));
        }
        for (i, key) in [(cue, "--cue-ball"), (object, "--pot")] {
            let s = setup.balls[i].state;
            if s.motion != snooker_engine::Motion::Stationary {
                return Err(bad(
                    key,
                    format!(
                        "ball \"{}\" must be at rest on the cloth to plan",
                        setup.balls[i].id
                    ),
                ));
            }
        }
        let pocket = setup
            .table
            .pockets
            .iter()
            .position(|pk| pk.name == request.pocket)
            .ok_or_else(|| {
                let names: Vec<&str> = setup
                    .table
                    .pockets
                    .iter()
                    .map(|p| p.name.as_str())
                    .collect();
                bad(
                    "--pocket",
                    format!(
                        "no pocket \"{}\" on this table (it has {})",
                        request.pocket,
                        if names.is_empty() {
                            "none".to_string()
                        } else {
                            names.join(", ")
                        }
                    ),
                )
            })?;
        let [x, y] = request.target;
        if !(x.is_finite() && y.is_finite()) {
            return Err(bad("--cue-to", "the target must be finite"));
        }
        let target = Vec3::new(x, y, r);
        if let Some(why) = setup.table.placement_error(target, r) {
            return Err(bad("--cue-to", format!("a ball cannot stop there: {why}")));
        }
        for (i, b) in setup.balls.iter().enumerate() {
            let gap = (b.state.pos - target).xy().norm();
            if i != cue && i != object && b.state.motion.in_play() && gap < 2.0 * r {
                return Err(bad(
                    "--cue-to",
                    format!(
                        "the cue ball would overlap \"{}\" there ({:.1} mm apart, centres)",
                        b.id,
                        gap * 1e3
                    ),
                ));
            }
        }
        if !(request.tolerance.is_finite() && request.tolerance > 0.0) {
            return Err(bad("--tolerance", "must be a positive distance, m"));
        }
        if request.samples == 0 {
            return Err(bad("--samples", "at least one sample"));
        }
        Ok(Problem {
            setup,
            options: scene.options,
            request,
            cue,
            object,
            pocket,
            target,
            shots: AtomicU64::new(0),
        })
    }

    /// Shots simulated so far.
    pub fn shots(&self) -> u64 {
        self.shots.load(Ordering::Relaxed)
    }

    pub(crate) fn count_shot(&self) {
        self.shots.fetch_add(1, Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::BallState;
    use snooker_engine::cue::{self, Cue};

    #[test]
    fn offset_bounds_are_the_engines_at_the_elevations_allowed() {
        let p = Params::default();
        let bounds = |spec: &str| Bounds::default_for(&p).with_spec(spec, &p);
        // A level cue: the axis within miscue_limit (R + r) = 18.1 mm of the centre.
        assert!(bounds("side=-0.018..0.018,height=-0.018..0.018").is_ok());
        let e = bounds("height=0.0..0.019").unwrap_err().to_string();
        assert!(e.contains("18.1 mm"), "{e}");
        // Issue 21's massé, a 40 mm height offset at 1.2 rad, is within them; given in either
        // order.
        assert!(bounds("elevation=0..1.2,height=0..0.04").is_ok());
        assert!(bounds("height=0..0.04,elevation=0..1.2").is_ok());
        assert!(bounds("elevation=0..1.2,height=0..0.051").is_err());
        // The limits say what the engine does: just inside, a strike; just beyond, a miscue.
        let ball = BallState::at_rest(1.0, 0.9, p.ball_radius);
        let limit = p.miscue_limit * (p.ball_radius + p.cue_tip_radius) / 1.2f64.cos();
        for (k, ok) in [(0.999, true), (1.001, false)] {
            let c = Cue {
                speed: 2.0,
                aim: 0.0,
                offset: [0.0, k * limit],
                elevation: 1.2,
            };
            assert_eq!(cue::strike(&ball, &c, &p).is_ok(), ok, "{k}");
        }
    }
}
