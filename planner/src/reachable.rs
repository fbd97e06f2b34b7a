//! Positions with a known answer, for measuring the planner (issue 13's accuracy test and
//! bench): a random position (cue ball, object ball, 0-6 other balls, at least three radii
//! apart, on the 12 ft table), a random strike that pots the object ball, and the cue ball's
//! end as the target. A plan that reaches the target then exists: the strike itself. The
//! strike may be any pot ([`Pots::Any`]: direct, off cushions, through another ball, kissed)
//! or only a clean direct one ([`Pots::Direct`], the bench's positions).

use crate::line::ShotKind;
use crate::trial::{classify, first_hit};
use rand::RngExt;
use snooker_engine::{Cue, EventKind, Motion, Params, SnookerDims, simulate};
use snooker_scene::{BallSpec, SceneFile, parse};

/// Which potting strikes a draw keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pots {
    /// Any strike that pots the object ball with the cue ball left on the table.
    Any,
    /// Only those where the cue ball hits the object ball first and it meets nothing (no
    /// cushion, jaw or ball) on its way into the pocket.
    Direct,
}

/// Ids of the balls placed: the cue ball, the object ball, then the others.
const IDS: [&str; 8] = ["cue", "obj", "b1", "b2", "b3", "b4", "b5", "b6"];
/// Balls are placed at least this far (m) from the cushion noses.
const MARGIN: f64 = 0.1;

/// A position and a clean direct pot from it.
#[derive(Debug, Clone)]
pub struct Reachable {
    /// The scene file's text: the balls (ids from `"cue"`, `"obj"`, `"b1"`..), no strike.
    pub text: String,
    /// The pocket the strike pots `"obj"` into.
    pub pocket: String,
    /// Where that strike leaves the cue ball (m): a target the planner can reach.
    pub target: [f64; 2],
    /// The strike.
    pub strike: Cue,
    /// What kind of pot it is.
    pub kind: ShotKind,
}

/// A scene text with `balls` at (x, y).
fn scene_text(balls: &[(&str, [f64; 2])]) -> String {
    balls
        .iter()
        .fold(SceneFile::new(), |scene, &(id, pos)| {
            scene.with_ball(BallSpec::at(id, pos))
        })
        .to_toml()
}

/// A random position and a random strike from it (speed 0.5-5 m/s, a cut within 0.8 of the
/// thinnest, tip offsets within 8 mm, level cue); `None` when the strike pots nothing as
/// `pots` asks (draw again: about one in eight pots cleanly and directly).
pub fn draw(rng: &mut impl RngExt, pots: Pots) -> Option<Reachable> {
    let dims = SnookerDims::default();
    let r = Params::default().ball_radius;
    let others = rng.random_range(0..=6);
    let mut balls: Vec<(&str, [f64; 2])> = Vec::new();
    for id in IDS.iter().take(2 + others) {
        for _ in 0..100 {
            let p = [
                rng.random_range(MARGIN..dims.length - MARGIN),
                rng.random_range(MARGIN..dims.width - MARGIN),
            ];
            let clear = balls
                .iter()
                .all(|(_, q)| (p[0] - q[0]).hypot(p[1] - q[1]) > 3.0 * r);
            if clear {
                balls.push((id, p));
                break;
            }
        }
    }
    if balls.len() < 2 {
        return None;
    }
    let text = scene_text(&balls);
    let scene = parse(&text, "case.toml").ok()?;
    let (c, o) = (balls[0].1, balls[1].1);
    let (dx, dy) = (o[0] - c[0], o[1] - c[1]);
    // Half the angle within which the cue ball meets the object ball at all.
    let half = (2.0 * r / dx.hypot(dy)).min(1.0).asin();
    let strike = Cue {
        speed: rng.random_range(0.5..5.0),
        aim: dy.atan2(dx) + rng.random_range(-0.8..0.8) * half,
        offset: [
            rng.random_range(-0.008..0.008),
            rng.random_range(-0.008..0.008),
        ],
        elevation: 0.0,
    };
    let mut setup = scene.setup.clone();
    setup.balls[0].strike(&strike, &setup.params).ok()?;
    let shot = simulate(&setup, &scene.options).ok()?;
    let cue_end = shot.final_states()[0];
    if cue_end.motion != Motion::Stationary {
        return None;
    }
    // Clean and direct: the cue ball hits the object ball first, which then meets nothing.
    let clean = || match first_hit(&shot, 0) {
        Some((1, contact)) => !shot.events.iter().any(|e| {
            e.t > contact.t
                && e.balls.contains(&1)
                && matches!(e.kind, EventKind::BallBall | EventKind::BallCushion)
        }),
        _ => false,
    };
    for pocket in &scene.setup.table.pockets {
        let Some(kind) = classify(&shot, 0, 1, &pocket.name) else {
            continue;
        };
        if pots == Pots::Direct && !clean() {
            return None;
        }
        return Some(Reachable {
            text,
            pocket: pocket.name.clone(),
            target: [cue_end.pos.x, cue_end.pos.y],
            strike,
            kind,
        });
    }
    None
}
