//! What is asked of the planner (the ball to pot, the pocket, the cue ball's target, the
//! limits of the search, the execution noise), checked against the scene once, up front.

use crate::cancel::Cancel;
use snooker_engine::cue::{MAX_CUE_SPEED, MAX_ELEVATION};
use snooker_engine::{Params, Setup, SimOptions, Vec3};
use snooker_scene::Scene;
use std::sync::atomic::{AtomicU64, Ordering};

use crate::line::{Line, ShotKind};
pub use crate::noise::{Noise, NoiseComponent};

/// A field of a planning request, as errors name it: the library speaks of the request's own
/// fields (`pot`, `bounds.speed`, `noise.aim`), and each front end says how its user spelled
/// them (a command-line flag, a Python argument).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RequestField {
    /// [`Request::cue_ball`].
    CueBall,
    /// [`Request::pot`].
    Pot,
    /// [`Request::pocket`].
    Pocket,
    /// [`Request::target`].
    Target,
    /// [`Request::tolerance`].
    Tolerance,
    /// [`Request::samples`].
    Samples,
    /// [`Request::alternatives`].
    Alternatives,
    /// One interval of [`Request::bounds`].
    Bounds(StrikeVariable),
    /// One standard deviation of [`Request::noise`].
    Noise(NoiseComponent),
    /// [`Request::kinds`].
    Kinds,
    /// [`Request::plant_balls`].
    PlantBalls,
}

impl std::fmt::Display for RequestField {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            RequestField::CueBall => f.write_str("cue_ball"),
            RequestField::Pot => f.write_str("pot"),
            RequestField::Pocket => f.write_str("pocket"),
            RequestField::Target => f.write_str("target"),
            RequestField::Tolerance => f.write_str("tolerance"),
            RequestField::Samples => f.write_str("samples"),
            RequestField::Alternatives => f.write_str("alternatives"),
            RequestField::Bounds(v) => write!(f, "bounds.{}", v.name()),
            RequestField::Noise(c) => write!(f, "noise.{}", c.name()),
            RequestField::Kinds => f.write_str("kinds"),
            RequestField::PlantBalls => f.write_str("plant_balls"),
        }
    }
}

/// A strike variable the search ranges over ([`Bounds`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StrikeVariable {
    /// Cue speed, m/s.
    Speed,
    /// Cue elevation, rad.
    Elevation,
    /// Side offset, m.
    Side,
    /// Height offset, m.
    Height,
}

impl StrikeVariable {
    /// All of them, in the order the bounds list them.
    pub const ALL: [StrikeVariable; 4] = [
        StrikeVariable::Speed,
        StrikeVariable::Elevation,
        StrikeVariable::Side,
        StrikeVariable::Height,
    ];

    /// Its name (`speed`, `elevation`, `side`, `height`).
    pub fn name(self) -> &'static str {
        match self {
            StrikeVariable::Speed => "speed",
            StrikeVariable::Elevation => "elevation",
            StrikeVariable::Side => "side",
            StrikeVariable::Height => "height",
        }
    }

    /// Its unit.
    pub fn unit(self) -> &'static str {
        match self {
            StrikeVariable::Speed => "m/s",
            StrikeVariable::Elevation => "rad",
            StrikeVariable::Side | StrikeVariable::Height => "m",
        }
    }

    /// The variable of that name.
    pub fn from_name(name: &str) -> Option<StrikeVariable> {
        Self::ALL.into_iter().find(|v| v.name() == name)
    }
}

/// Why there is no plan.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlanError {
    /// The request does not make sense for this scene (exit 2 in the command).
    #[error("{field}: {reason}")]
    BadInput {
        /// The request's field at fault.
        field: RequestField,
        /// Why.
        reason: String,
    },
    /// No strike within the bounds pots the ball (exit 1 in the command).
    #[error("{0}")]
    CannotPot(String),
}

fn bad(field: RequestField, reason: impl Into<String>) -> PlanError {
    PlanError::BadInput {
        field,
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

    /// The interval of variable `v`.
    pub fn get(&self, v: StrikeVariable) -> Interval {
        match v {
            StrikeVariable::Speed => self.speed,
            StrikeVariable::Elevation => self.elevation,
            StrikeVariable::Side => self.side,
            StrikeVariable::Height => self.height,
        }
    }

    /// Sets the interval of variable `v`.
    pub fn set(&mut self, v: StrikeVariable, iv: Interval) {
        match v {
            StrikeVariable::Speed => self.speed = iv,
            StrikeVariable::Elevation => self.elevation = iv,
            StrikeVariable::Side => self.side = iv,
            StrikeVariable::Height => self.height = iv,
        }
    }

    /// The engine's limits on variable `v` for parameters `p`, with the elevations `self`
    /// allows: the cue's speed and elevation ranges, and offsets at which the cue's axis passes
    /// within the miscue limit of the centre (`cue.rs`, thesis eq. 7.7: the contact lies
    /// miscue_limit R from the axis when the axis passes miscue_limit (R + r) from the centre).
    /// A height offset is foreshortened by cos(elevation), so a steeper cue allows a larger one.
    pub fn limits(&self, v: StrikeVariable, p: &Params) -> Interval {
        let reach = p.miscue_limit * (p.ball_radius + p.cue_tip_radius);
        let (lo, hi) = match v {
            StrikeVariable::Speed => (1e-3, MAX_CUE_SPEED),
            StrikeVariable::Elevation => (0.0, MAX_ELEVATION),
            StrikeVariable::Side => (-reach, reach),
            StrikeVariable::Height => {
                let h = reach / self.elevation.hi.cos();
                (-h, h)
            }
        };
        Interval { lo, hi }
    }

    /// Checks every interval (in the order of [`StrikeVariable::ALL`], elevation before the
    /// offsets it limits): finite, ordered, and within [`Bounds::limits`].
    pub fn check(&self, p: &Params) -> Result<(), PlanError> {
        for v in StrikeVariable::ALL {
            let iv = self.get(v);
            let field = RequestField::Bounds(v);
            if !(iv.lo.is_finite() && iv.hi.is_finite()) {
                return Err(bad(field, "the ends must be finite numbers"));
            }
            if iv.lo > iv.hi {
                return Err(bad(field, "the low end is above the high end"));
            }
            let allowed = self.limits(v, p);
            if iv.lo < allowed.lo || iv.hi > allowed.hi {
                let why = match v {
                    StrikeVariable::Side | StrikeVariable::Height => format!(
                        ": beyond, the cue's axis passes more than miscue_limit (R + r) = {:.1} mm \
                         from the centre at every elevation up to {:.4} rad, a miscue",
                        p.miscue_limit * (p.ball_radius + p.cue_tip_radius) * 1e3,
                        self.elevation.hi
                    ),
                    _ => String::new(),
                };
                return Err(bad(
                    field,
                    format!(
                        "outside the engine's strike limits [{:.4}, {:.4}] {}{why}",
                        allowed.lo,
                        allowed.hi,
                        v.unit()
                    ),
                ));
            }
        }
        Ok(())
    }
}

/// Most Monte Carlo samples a request may ask per shot ([`Request::samples`]): a pot
/// probability to a few parts in ten thousand, and one record each held in memory at once.
pub const MAX_SAMPLES: usize = 1_000_000;

/// Most alternatives a request may ask for ([`Request::alternatives`]): each is a shot kept
/// and sampled; a count past this is a typo (`usize::MAX` overflowed the search's count).
pub const MAX_ALTERNATIVES: usize = 1000;

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
    /// The kinds of pot tried (direct pots first, the others when those do not reach the
    /// target).
    pub kinds: Vec<ShotKind>,
    /// The balls a plant may strike first (ids); None: any ball.
    pub plant_balls: Option<Vec<String>>,
}

impl Request {
    /// A request with the default bounds (for `p`), the standard noise ([`Noise::STANDARD`]),
    /// 256 samples, 3 alternatives and a 1 mm tolerance.
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
            kinds: ShotKind::ALL.to_vec(),
            plant_balls: None,
        }
    }
}

/// A checked request on a scene: indices resolved, the cue ball as it lies (any strike in the
/// scene undone), and a count of the shots simulated.
#[derive(Debug)]
pub struct Problem {
    // Private to the crate, read through the accessors below: a checked problem cannot be
    // changed into an unchecked one (a NaN target, a pocket index past the table's).
    /// The position, the cue ball at rest where it lies.
    pub(crate) setup: Setup,
    /// The scene's simulation limits (as `snooker simulate` uses them).
    pub(crate) options: SimOptions,
    /// The request.
    pub(crate) request: Request,
    /// Index of the cue ball.
    pub(crate) cue: usize,
    /// Index of the object ball.
    pub(crate) object: usize,
    /// Index of the pocket in the table's pockets.
    pub(crate) pocket: usize,
    /// The cue ball's target, m (z = R).
    pub(crate) target: Vec3,
    /// For each ball, whether a plant may strike it first.
    plant_ok: Vec<bool>,
    shots: AtomicU64,
    unfinished: AtomicU64,
    cancel: Cancel,
}

impl Problem {
    /// The position, the cue ball at rest where it lies.
    pub fn setup(&self) -> &Setup {
        &self.setup
    }

    /// The scene's simulation limits (as `snooker simulate` uses them).
    pub fn options(&self) -> &SimOptions {
        &self.options
    }

    /// The request, as checked.
    pub fn request(&self) -> &Request {
        &self.request
    }

    /// Index of the cue ball in the setup's balls.
    pub fn cue(&self) -> usize {
        self.cue
    }

    /// Index of the object ball in the setup's balls.
    pub fn object(&self) -> usize {
        self.object
    }

    /// Index of the pocket in the table's pockets.
    pub fn pocket(&self) -> usize {
        self.pocket
    }

    /// The cue ball's target, m (z = R).
    pub fn target(&self) -> Vec3 {
        self.target
    }

    /// Checks `request` against `scene`.
    pub fn new(scene: &Scene, request: Request) -> Result<Problem, PlanError> {
        let mut setup = scene.setup.clone();
        if let Some(s) = &scene.strike {
            // The scene's own strike is ignored: the cue ball lies where it was before it.
            setup.balls[s.index].state = s.before;
        }
        let problem = Problem::for_setup(setup, scene.options, request)?;
        problem.check_target()?;
        Ok(problem)
    }

    /// Checks `request` against the balls of `setup` (at rest, no strike applied), simulated
    /// with `options`: as [`Problem::new`], but the target is not checked (a caller valuing
    /// strokes by its own [`crate::explore::Objective`] may give any point, such as where the
    /// cue ball lies).
    pub fn for_setup(
        setup: Setup,
        options: SimOptions,
        request: Request,
    ) -> Result<Problem, PlanError> {
        let p = setup.params;
        let r = p.ball_radius;
        let index = |field: RequestField, id: &str| {
            setup.balls.iter().position(|b| b.id == id).ok_or_else(|| {
                let ids: Vec<&str> = setup.balls.iter().map(|b| b.id.as_str()).collect();
                bad(
                    field,
                    format!("no ball \"{id}\" in the scene (it has {})", ids.join(", ")),
                )
            })
        };
        let cue = index(RequestField::CueBall, &request.cue_ball)?;
        let object = index(RequestField::Pot, &request.pot)?;
        if object == cue {
            return Err(bad(
                RequestField::Pot,
                "the cue ball cannot be the ball to pot",
            ));
        }
        for (i, field) in [(cue, RequestField::CueBall), (object, RequestField::Pot)] {
            let s = setup.balls[i].state;
            if s.motion != snooker_engine::Motion::Stationary {
                return Err(bad(
                    field,
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
                    RequestField::Pocket,
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
            return Err(bad(RequestField::Target, "the target must be finite"));
        }
        let target = Vec3::new(x, y, r);
        if !(request.tolerance.is_finite() && request.tolerance > 0.0) {
            return Err(bad(
                RequestField::Tolerance,
                "must be a positive distance, m",
            ));
        }
        if request.samples == 0 {
            return Err(bad(RequestField::Samples, "at least one sample"));
        }
        if request.samples > MAX_SAMPLES {
            return Err(bad(
                RequestField::Samples,
                format!("at most {MAX_SAMPLES} samples, got {}", request.samples),
            ));
        }
        if request.alternatives > MAX_ALTERNATIVES {
            return Err(bad(
                RequestField::Alternatives,
                format!(
                    "at most {MAX_ALTERNATIVES} alternatives, got {}",
                    request.alternatives
                ),
            ));
        }
        request.bounds.check(&p)?;
        request.noise.check()?;
        if request.kinds.is_empty() {
            return Err(bad(RequestField::Kinds, "at least one kind of pot"));
        }
        let plant_ok = match &request.plant_balls {
            None => vec![true; setup.balls.len()],
            Some(ids) => {
                let mut ok = vec![false; setup.balls.len()];
                for id in ids {
                    let b = index(RequestField::PlantBalls, id)?;
                    // A plant strikes another ball first: the cue ball and the ball potted
                    // cannot be that ball (naming one would be a typo, not a plant).
                    if b == cue || b == object {
                        return Err(bad(
                            RequestField::PlantBalls,
                            format!(
                                "\"{id}\" is the ball struck or the ball potted, not a ball to plant through"
                            ),
                        ));
                    }
                    ok[b] = true;
                }
                ok
            }
        };
        Ok(Problem {
            setup,
            options,
            request,
            cue,
            object,
            pocket,
            target,
            plant_ok,
            shots: AtomicU64::new(0),
            unfinished: AtomicU64::new(0),
            cancel: Cancel::new(),
        })
    }

    /// Checks that a ball could stop at the target: on the cloth, clear of every ball but the
    /// cue ball and the object ball.
    fn check_target(&self) -> Result<(), PlanError> {
        let (target, r, cue, object) = (
            self.target,
            self.setup.params.ball_radius,
            self.cue,
            self.object,
        );
        if let Some(why) = self.setup.table.placement_error(target, r) {
            return Err(bad(
                RequestField::Target,
                format!("a ball cannot stop there: {why}"),
            ));
        }
        for (i, b) in self.setup.balls.iter().enumerate() {
            let gap = (b.state.pos - target).xy().norm();
            if i != cue && i != object && b.state.motion.in_play() && gap < 2.0 * r {
                return Err(bad(
                    RequestField::Target,
                    format!(
                        "the cue ball would overlap \"{}\" there ({:.1} mm apart, centres)",
                        b.id,
                        gap * 1e3
                    ),
                ));
            }
        }
        Ok(())
    }

    /// True when the cue ball may strike ball `b` first: the object ball, or a ball a plant
    /// may strike first.
    pub fn may_hit_first(&self, b: usize) -> bool {
        b == self.object
            || (self.request.kinds.contains(&ShotKind::Plant)
                && b != self.cue
                && self.plant_ok.get(b).copied().unwrap_or(false))
    }

    /// The lines the request allows ([`Problem::lines`] of its kinds, plants through the
    /// balls it allows).
    pub fn requested_lines(&self) -> Vec<Line> {
        self.lines()
            .into_iter()
            .filter(|l| self.request.kinds.contains(&l.kind))
            .filter(|l| l.kind != ShotKind::Plant || l.ball.is_some_and(|b| self.may_hit_first(b)))
            .collect()
    }

    /// Shots simulated so far.
    pub fn shots(&self) -> u64 {
        self.shots.load(Ordering::Relaxed)
    }

    pub(crate) fn count_shot(&self) {
        self.shots.fetch_add(1, Ordering::Relaxed);
    }

    /// Shots simulated so far that could not finish within the scene's `[sim]` limits.
    pub fn unfinished(&self) -> u64 {
        self.unfinished.load(Ordering::Relaxed)
    }

    pub(crate) fn count_unfinished(&self) {
        self.unfinished.fetch_add(1, Ordering::Relaxed);
    }

    /// The problem watching `cancel`: once it is raised no further shot is simulated, and the
    /// plan (an error or a partial answer) is void.
    pub fn with_cancel(mut self, cancel: Cancel) -> Problem {
        self.cancel = cancel;
        self
    }

    /// True once the problem's cancellation flag is raised.
    pub fn cancelled(&self) -> bool {
        self.cancel.is_cancelled()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::BallState;
    use snooker_engine::cue::{self, Cue};

    /// The default bounds with the given intervals (side, height, elevation), checked.
    fn checked(p: &Params, set: &[(StrikeVariable, f64, f64)]) -> Result<Bounds, PlanError> {
        let mut b = Bounds::default_for(p);
        for &(v, lo, hi) in set {
            b.set(v, Interval { lo, hi });
        }
        b.check(p).map(|()| b)
    }

    #[test]
    fn offset_bounds_are_the_engines_at_the_elevations_allowed() {
        use StrikeVariable::{Elevation, Height, Side};
        let p = Params::default();
        // A level cue: the axis within miscue_limit (R + r) = 18.1 mm of the centre (issue 21:
        // the bounds said 13.1 mm, miscue_limit R, which is where the contact lies, not the axis).
        assert!(checked(&p, &[(Side, -0.018, 0.018), (Height, -0.018, 0.018)]).is_ok());
        let e = checked(&p, &[(Height, 0.0, 0.019)])
            .unwrap_err()
            .to_string();
        assert!(e.contains("18.1 mm"), "{e}");
        // Issue 21's massé, a 40 mm height offset at 1.2 rad, is within them.
        assert!(checked(&p, &[(Elevation, 0.0, 1.2), (Height, 0.0, 0.04)]).is_ok());
        assert!(checked(&p, &[(Elevation, 0.0, 1.2), (Height, 0.0, 0.051)]).is_err());
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
