//! One strike through the engine, exactly as `snooker simulate` would run the scene with that
//! `[cue]`, and what it did: potted or not, fouls, where the cue ball stopped, and how far
//! off the object ball left for the pocket.

use crate::problem::Problem;
use snooker_engine::cue::Cue;
use snooker_engine::{EventKind, Motion, Vec3, simulate};

/// Why a shot is not a plan (a foul or a miss, in the snooker sense).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Fault {
    /// The cue ball hit another ball first.
    WrongBallFirst,
    /// The cue ball hit no ball.
    NoContact,
    /// The cue ball was potted or left the table.
    CueBallLost,
    /// The object ball was not potted in the pocket asked for.
    NotPotted,
}

/// The cue ball's way after the object ball: the cushions it met (names, in order, at most
/// three) and whether it was struck below centre (screw), near it (stun) or above (follow).
/// Shots on different routes are genuinely different shots.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Route {
    /// Cushions met by the cue ball after the object ball.
    pub cushions: Vec<String>,
    /// -1 screw, 0 stun, +1 follow.
    pub spin: i8,
}

/// What one strike did.
#[derive(Debug, Clone)]
pub struct Trial {
    /// The strike.
    pub cue: Cue,
    /// None when the object ball went into the pocket with no foul.
    pub fault: Option<Fault>,
    /// Where the cue ball stopped (plan), m.
    pub cue_final: Vec3,
    /// The object ball's centre and velocity just after the cue ball hit it; None if the cue
    /// ball did not hit it first.
    pub departure: Option<(Vec3, Vec3)>,
    /// The cue ball's route.
    pub route: Route,
    /// True when the object ball met nothing (cushion, jaw or ball) between the cue ball and
    /// the pocket: a direct pot, the kind the planner aims.
    pub direct: bool,
}

impl Trial {
    /// True for a pot without a foul.
    pub fn pots(&self) -> bool {
        self.fault.is_none()
    }
}

/// Signed angle from `a` to `b` (plan), rad.
pub fn angle(a: Vec3, b: Vec3) -> f64 {
    (a.x * b.y - a.y * b.x).atan2(a.x * b.x + a.y * b.y)
}

impl Problem {
    /// Strikes the cue ball with `cue` and simulates the shot; None when the strike is not
    /// possible (a miscue), the shot does not simulate, or the plan is cancelled.
    pub fn trial(&self, cue: &Cue) -> Option<Trial> {
        if self.cancelled() {
            return None;
        }
        let mut setup = self.setup.clone();
        setup.balls[self.cue].strike(cue, &self.setup.params).ok()?;
        self.count_shot();
        let shot = simulate(&setup, &self.options).ok()?;
        let (c, o) = (self.cue, self.object);
        let pocket = &setup.table.pockets[self.pocket];
        let first = shot
            .events
            .iter()
            .find(|e| e.kind == EventKind::BallBall && e.balls.contains(&c));
        let (mut fault, mut departure, mut contact_t) = (None, None, f64::INFINITY);
        match first {
            None => fault = Some(Fault::NoContact),
            Some(e) if !e.balls.contains(&o) => fault = Some(Fault::WrongBallFirst),
            Some(e) => {
                let k = e.balls.iter().position(|&b| b == o).unwrap_or(0);
                departure = Some((e.after[k].pos, e.after[k].vel));
                contact_t = e.t;
            }
        }
        let finals = shot.final_states();
        if fault.is_none() && finals[c].motion != Motion::Stationary {
            fault = Some(Fault::CueBallLost);
        }
        let potted_there = shot.events.iter().any(|e| {
            e.kind == EventKind::BallPocket
                && e.balls.first() == Some(&o)
                && e.feature.as_deref() == Some(pocket.name.as_str())
        });
        if fault.is_none() && !potted_there {
            fault = Some(Fault::NotPotted);
        }
        let direct = !shot.events.iter().any(|e| {
            e.t > contact_t
                && e.balls.contains(&o)
                && matches!(e.kind, EventKind::BallBall | EventKind::BallCushion)
        });
        let cushions = shot
            .events
            .iter()
            .filter(|e| e.t > contact_t && e.kind == EventKind::BallCushion && e.balls[0] == c)
            .filter_map(|e| e.feature.clone())
            .take(3)
            .collect();
        let third = setup.params.ball_radius / 3.0;
        let spin = if cue.offset[1] < -third {
            -1
        } else if cue.offset[1] > third {
            1
        } else {
            0
        };
        Some(Trial {
            cue: *cue,
            fault,
            cue_final: finals[c].pos,
            departure,
            direct,
            route: Route { cushions, spin },
        })
    }

    /// Distance from where the trial's cue ball stopped to the target (plan), m.
    pub fn distance(&self, t: &Trial) -> f64 {
        (t.cue_final - self.target).xy().norm()
    }
}
