//! One scene through the parser and the engine, every invariant checked: how it ended, and
//! what (if anything) is wrong with it.

use crate::generate::{Generated, Kind, unphysical_cloth};
use snooker_engine::audit::{self, MAX_OVERLAP};
use snooker_engine::impact::separation;
use snooker_engine::motion::Transition;
use snooker_engine::{EventKind, Motion, Shot, SimError, SimOptions, simulate};
use std::hash::{DefaultHasher, Hash, Hasher};
use std::panic::{AssertUnwindSafe, catch_unwind};

/// Simulated time after which a shot on a near-frictionless cloth is stopped, s.
pub const UNPHYSICAL_MAX_TIME: f64 = 30.0;
/// Events after which a shot on a near-frictionless cloth is stopped.
pub const UNPHYSICAL_MAX_EVENTS: usize = 5_000;

/// How a scene ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SceneEnding {
    /// Simulated; every ball at rest, pocketed or off the table.
    AtRest,
    /// Rejected by the parser with a message (exit 2).
    Rejected,
    /// Balls still moving after `max_time` (exit 1): physical on a near-frictionless cloth.
    DidNotStop,
    /// The event cap (exit 1): physical only on a near-frictionless cloth.
    EventCap,
    /// Too many events at one instant (exit 1).
    Stuck,
    /// An impact model failed (exit 1, "internal error").
    ImpactFailed,
    /// A non-finite number appeared (exit 1, "internal error").
    NonFinite,
    /// A panic.
    Panicked,
}

impl SceneEnding {
    /// Its name in reports.
    pub fn name(self) -> &'static str {
        match self {
            SceneEnding::AtRest => "at rest",
            SceneEnding::Rejected => "rejected",
            SceneEnding::DidNotStop => "still moving at max_time",
            SceneEnding::EventCap => "event cap",
            SceneEnding::Stuck => "stuck at an instant",
            SceneEnding::ImpactFailed => "impact failed",
            SceneEnding::NonFinite => "non-finite",
            SceneEnding::Panicked => "panic",
        }
    }
}

/// What a scene can reach, for the coverage table: every event kind, and the classes issue 21
/// found an earlier generator never reached (by name in reports).
pub const FEATURES: [&str; 22] = [
    "ball_ball",
    "ball_cushion",
    "ball_pocket",
    "ball_off_table",
    "lift_off",
    "landing",
    "slide_to_roll",
    "slide_to_spin",
    "slide_to_stop",
    "roll_to_spin",
    "roll_to_stop",
    "spin_to_stop",
    // A cushion, jaw or facing met by a ball in the air.
    "cushion_in_air",
    // A ball pocketed from the air.
    "pot_from_air",
    // A ball leaving over a jaw's rounded edge.
    "over_jaw",
    // A ball leaving over a pocket's back.
    "over_pocket_back",
    // A resting contact's micro-collision (approach at most RESTING_APPROACH).
    "micro_collision",
    // A strike with the cue at 60 degrees or steeper.
    "steep_cue",
    // A strike whose offset has a coordinate beyond R + r (valid only with a steep cue).
    "offset_beyond_r_plus_r",
    // A strike the cloth's friction acted on (`mu_strike_cloth` set, the cue inclined).
    "strike_cloth_friction",
    // A strike that made the ball jump (`e_bed` set, the cue inclined).
    "strike_jump",
    // A landing that bounced (`e_bed` set).
    "bounce",
];

/// The [`FEATURES`] `shot` of `scene` reached, as bits.
fn reached(scene: &snooker_scene::Scene, shot: &Shot) -> u32 {
    let feature = |name: &str| 1u32 << FEATURES.iter().position(|f| *f == name).unwrap_or(31);
    let mut bits = 0;
    for e in &shot.events {
        bits |= feature(e.kind.name());
        let from_air = e.before.iter().any(|s| s.motion == Motion::Airborne);
        let name = e.feature.as_deref().unwrap_or("");
        bits |= match e.kind {
            EventKind::BallCushion if from_air => feature("cushion_in_air"),
            EventKind::BallPocket if from_air => feature("pot_from_air"),
            EventKind::BallOffTable if name.ends_with(" jaw") => feature("over_jaw"),
            EventKind::BallOffTable if name.ends_with("/back") => feature("over_pocket_back"),
            EventKind::Transition(Transition::Landing)
                if e.after.iter().any(|s| s.motion == Motion::Airborne) =>
            {
                feature("bounce")
            }
            EventKind::BallBall
                if e.normal_speed
                    .is_some_and(|v| v <= separation::RESTING_APPROACH) =>
            {
                feature("micro_collision")
            }
            _ => 0,
        };
    }
    if let Some(s) = &scene.strike {
        let p = &scene.setup.params;
        if s.cue.elevation >= 60f64.to_radians() {
            bits |= feature("steep_cue");
        }
        if s.cue
            .offset
            .iter()
            .any(|v| v.abs() > p.ball_radius + p.cue_tip_radius)
        {
            bits |= feature("offset_beyond_r_plus_r");
        }
        if s.strike.cloth_friction.norm() > 0.0 {
            bits |= feature("strike_cloth_friction");
        }
        if s.strike.state.motion == Motion::Airborne {
            bits |= feature("strike_jump");
        }
    }
    bits & !(1 << 31)
}

/// What one scene did.
#[derive(Clone, Debug)]
pub struct SceneCheck {
    /// How it ended.
    pub ending: SceneEnding,
    /// Whether its parameters are a physical cloth's.
    pub physical: bool,
    /// Why not, if not.
    pub unphysical: Option<&'static str>,
    /// Why it fails the harness, if it does.
    pub failure: Option<String>,
    /// A hash of the result (every event's time, balls and states, the final states; or the
    /// error's message), so that a change meant to leave every bit alone can be checked.
    pub digest: u64,
    /// The [`FEATURES`] the shot reached, as bits (none for a shot that did not finish).
    pub reached: u32,
}

fn sim_ending(e: &SimError) -> SceneEnding {
    match e {
        SimError::Setup(_) => SceneEnding::Rejected,
        SimError::TooManyEvents { .. } => SceneEnding::EventCap,
        SimError::Stuck { .. } => SceneEnding::Stuck,
        SimError::DidNotStop { .. } => SceneEnding::DidNotStop,
        SimError::Impact { .. } => SceneEnding::ImpactFailed,
        SimError::NonFinite { .. } => SceneEnding::NonFinite,
    }
}

/// A shot's numbers as bits: its duration, every event's time, balls and states after, and the
/// final states.
fn bits(s: &Shot) -> Vec<u64> {
    let mut v: Vec<u64> = vec![s.duration.to_bits(), s.events.len() as u64];
    for e in &s.events {
        v.push(e.t.to_bits());
        v.extend(e.balls.iter().map(|&b| b as u64));
        v.extend(e.after.iter().flat_map(|st| st.to_bits()));
    }
    v.extend(s.final_states().iter().flat_map(|st| st.to_bits()));
    v
}

/// A hash of `x` that is the same on every run (std's SipHash with fixed keys; it may change
/// with the Rust toolchain, so digests are compared on one toolchain).
fn digest(x: impl Hash) -> u64 {
    let mut h = DefaultHasher::new();
    x.hash(&mut h);
    h.finish()
}

/// Runs `g` and checks it.
pub fn check(g: &Generated) -> SceneCheck {
    let run = catch_unwind(AssertUnwindSafe(|| check_inner(g)));
    run.unwrap_or_else(|panic| {
        let why = panic
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        SceneCheck {
            ending: SceneEnding::Panicked,
            physical: g.physical,
            unphysical: None,
            failure: Some(format!("panic: {why}")),
            digest: digest(why),
            reached: 0,
        }
    })
}

fn check_inner(g: &Generated) -> SceneCheck {
    let scene = match snooker_scene::parse(&g.text, "fuzz.toml") {
        Ok(s) => s,
        Err(e) => {
            // Only hostile scenes may be rejected; the message must name the file.
            let failure = (g.kind != Kind::Hostile)
                .then(|| format!("a valid scene was rejected: {e}"))
                .or_else(|| {
                    (!e.to_string().starts_with("fuzz.toml"))
                        .then(|| format!("the message does not name the file: {e}"))
                });
            return SceneCheck {
                ending: SceneEnding::Rejected,
                physical: g.physical,
                unphysical: None,
                digest: digest(e.to_string()),
                failure,
                reached: 0,
            };
        }
    };
    let unphysical = unphysical_cloth(&scene.setup.params);
    let physical = unphysical.is_none();
    let verdict = |ending, failure, digest| SceneCheck {
        ending,
        physical,
        unphysical,
        failure,
        digest,
        reached: 0,
    };
    // On a near-frictionless cloth not stopping is no failure: the shot is cut short (every
    // invariant still checked up to there), so that one such shot does not take minutes.
    let options = if physical {
        scene.options
    } else {
        SimOptions {
            max_time: scene.options.max_time.min(UNPHYSICAL_MAX_TIME),
            max_events: scene.options.max_events.min(UNPHYSICAL_MAX_EVENTS),
            ..scene.options
        }
    };
    let first = simulate(&scene.setup, &options);
    let second = simulate(&scene.setup, &options);
    let shot = match (first, second) {
        (Ok(a), Ok(b)) => {
            if bits(&a) != bits(&b) {
                return verdict(SceneEnding::AtRest, Some("not deterministic".into()), 0);
            }
            a
        }
        (Err(a), Err(b)) => {
            let ending = sim_ending(&a);
            let failure = if a != b {
                Some(format!("not deterministic: {a} / {b}"))
            } else {
                match ending {
                    SceneEnding::DidNotStop | SceneEnding::EventCap if !physical => None,
                    _ => Some(format!("{} (exit 1): {a}", ending.name())),
                }
            };
            return verdict(ending, failure, digest(a.to_string()));
        }
        (a, b) => {
            let why = format!("not deterministic: {:?} / {:?}", a.err(), b.err());
            return verdict(SceneEnding::AtRest, Some(why), 0);
        }
    };
    let mut broken = audit::events(&shot, MAX_OVERLAP);
    broken.extend(audit::positions(&scene.setup.table, &shot));
    SceneCheck {
        reached: reached(&scene, &shot),
        ..verdict(
            SceneEnding::AtRest,
            audit::report(&broken[..broken.len().min(5)]),
            digest(bits(&shot)),
        )
    }
}
