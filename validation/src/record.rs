//! What the cross-check compares, in a form both engines produce: the impacts in order (which
//! balls, which cushion or pocket, when, and the velocities and spins just after), the
//! slide-to-roll transitions, and where every ball ends.

use snooker_engine::motion::Transition;
use snooker_engine::{EventKind, Motion, Shot, Vec3};

/// What an impact involves.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Contact {
    /// Two balls, by index, the smaller first.
    Balls(usize, usize),
    /// A ball and a cushion, jaw or pocket facing (by the engine's name).
    Cushion(usize, String),
    /// A ball falling into a pocket (by name).
    Pocket(usize, String),
}

impl Contact {
    /// The balls involved, in order.
    pub fn balls(&self) -> Vec<usize> {
        match self {
            Contact::Balls(a, b) => vec![*a, *b],
            Contact::Cushion(a, _) | Contact::Pocket(a, _) => vec![*a],
        }
    }

    /// A short label with ball ids: "cue-red", "cue|right-baulk", "red>top-left".
    pub fn label(&self, ids: &[String]) -> String {
        match self {
            Contact::Balls(a, b) => format!("{}-{}", ids[*a], ids[*b]),
            Contact::Cushion(a, c) => format!("{}|{c}", ids[*a]),
            Contact::Pocket(a, p) => format!("{}>{p}", ids[*a]),
        }
    }
}

/// Velocity and spin of one ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Velocities {
    /// Velocity, m/s.
    pub vel: Vec3,
    /// Angular velocity, rad/s.
    pub spin: Vec3,
}

/// One impact.
#[derive(Clone, Debug, PartialEq)]
pub struct Impact {
    /// When the bodies touch, s.
    pub t: f64,
    /// What touches.
    pub contact: Contact,
    /// Velocity and spin of each ball of [`Contact::balls`] just after the impact.
    pub after: Vec<Velocities>,
    /// Approach speed along the contact normal just before (for a pot: the ball's speed), m/s.
    pub approach: f64,
}

/// A ball's sliding ending in rolling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roll {
    /// The ball.
    pub ball: usize,
    /// When, s.
    pub t: f64,
    /// Speed at that moment, m/s.
    pub speed: f64,
    /// When the slide began, s.
    pub slide_t: f64,
    /// Velocity and spin when the slide began.
    pub slide_start: Velocities,
}

/// Where a ball ends.
#[derive(Clone, Debug, PartialEq)]
pub struct Final {
    /// Centre, m.
    pub pos: Vec3,
    /// The pocket it fell into, if any.
    pub pocket: Option<String>,
}

/// Everything compared of one run of one engine.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// Ball ids, in the scene's order.
    pub ids: Vec<String>,
    /// Impacts in time order.
    pub impacts: Vec<Impact>,
    /// Slide-to-roll transitions in time order.
    pub rolls: Vec<Roll>,
    /// One per ball.
    pub finals: Vec<Final>,
    /// Time when every ball is at rest or pocketed, s.
    pub duration: f64,
}

impl Record {
    /// The record of a shot of our engine.
    pub fn from_shot(shot: &Shot) -> Record {
        let ids: Vec<String> = shot.tracks.iter().map(|t| t.id.clone()).collect();
        let mut impacts = Vec::new();
        let mut rolls = Vec::new();
        for e in &shot.events {
            let kin = |k: usize| Velocities {
                vel: e.after[k].vel,
                spin: e.after[k].spin,
            };
            let feature = || e.feature.clone().unwrap_or_default();
            match e.kind {
                EventKind::BallBall => {
                    let (a, b) = (e.balls[0], e.balls[1]);
                    let (contact, after) = if a < b {
                        (Contact::Balls(a, b), vec![kin(0), kin(1)])
                    } else {
                        (Contact::Balls(b, a), vec![kin(1), kin(0)])
                    };
                    impacts.push(Impact {
                        t: e.t,
                        contact,
                        after,
                        approach: e.normal_speed.unwrap_or(0.0),
                    });
                }
                EventKind::BallCushion => impacts.push(Impact {
                    t: e.t,
                    contact: Contact::Cushion(e.balls[0], feature()),
                    after: vec![kin(0)],
                    approach: e.normal_speed.unwrap_or(0.0),
                }),
                EventKind::BallPocket => impacts.push(Impact {
                    t: e.t,
                    contact: Contact::Pocket(e.balls[0], feature()),
                    after: vec![kin(0)],
                    approach: e.before[0].vel.xy().norm(),
                }),
                EventKind::Transition(Transition::SlideToRoll) => {
                    let ball = e.balls[0];
                    let segs = &shot.tracks[ball].segments;
                    // The sliding segment is the last one that started before this event.
                    let start = segs
                        .iter()
                        .rev()
                        .find(|s| s.t < e.t && s.state.motion == Motion::Sliding)
                        .map_or((0.0, e.before[0]), |s| (s.t, s.state));
                    rolls.push(Roll {
                        ball,
                        t: e.t,
                        speed: e.after[0].vel.norm(),
                        slide_t: start.0,
                        slide_start: Velocities {
                            vel: start.1.vel,
                            spin: start.1.spin,
                        },
                    });
                }
                EventKind::Transition(_) => {}
            }
        }
        let pockets: Vec<Option<String>> = (0..ids.len())
            .map(|i| {
                shot.events
                    .iter()
                    .find(|e| e.kind == EventKind::BallPocket && e.balls[0] == i)
                    .and_then(|e| e.feature.clone())
            })
            .collect();
        let finals = shot
            .final_states()
            .into_iter()
            .zip(pockets)
            .map(|(s, pocket)| Final {
                pos: s.pos,
                pocket: if s.motion == Motion::Pocketed {
                    pocket
                } else {
                    None
                },
            })
            .collect();
        Record {
            ids,
            impacts,
            rolls,
            finals,
            duration: shot.duration,
        }
    }

    /// The same record reduced to what both engines can resolve: impacts closing slower than
    /// `min_approach` dropped (resting contacts: rapier's pack contacts carry tiny impulses
    /// every step, our engine turns sustained contacts into micro-collisions at
    /// [`snooker_engine::impact::MIN_SEPARATION`]), and runs of impacts of the same contact
    /// closer than `window` seconds merged into one (the first time, the last state after): a
    /// time-stepped solver cannot tell apart contacts that close within one step.
    pub fn normalised(&self, window: f64, min_approach: f64) -> Record {
        let mut impacts: Vec<Impact> = Vec::new();
        let mut last_t: Vec<(Contact, f64, usize)> = Vec::new();
        let resolved = self
            .impacts
            .iter()
            .filter(|i| matches!(i.contact, Contact::Pocket(..)) || i.approach >= min_approach);
        for imp in resolved {
            if let Some(entry) = last_t.iter_mut().find(|(c, _, _)| *c == imp.contact) {
                if imp.t - entry.1 <= window {
                    entry.1 = imp.t;
                    impacts[entry.2].after = imp.after.clone();
                    continue;
                }
                entry.1 = imp.t;
                entry.2 = impacts.len();
            } else {
                last_t.push((imp.contact.clone(), imp.t, impacts.len()));
            }
            impacts.push(imp.clone());
        }
        Record {
            impacts,
            ..self.clone()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn imp(t: f64, a: usize, b: usize, v: f64) -> Impact {
        Impact {
            t,
            contact: Contact::Balls(a, b),
            after: vec![
                Velocities {
                    vel: Vec3::new(v, 0.0, 0.0),
                    spin: Vec3::zeros(),
                };
                2
            ],
            approach: 1.0,
        }
    }

    #[test]
    fn normalising_joins_close_repeats_and_drops_resting_contacts() {
        let r = Record {
            ids: vec!["a".into(), "b".into(), "c".into()],
            impacts: vec![
                imp(0.1, 0, 1, 1.0),
                imp(0.10005, 1, 2, 2.0),
                imp(0.1001, 0, 1, 3.0),
                imp(0.5, 0, 1, 4.0),
                Impact {
                    approach: 0.1,
                    ..imp(0.7, 0, 1, 5.0)
                },
            ],
            rolls: vec![],
            finals: vec![],
            duration: 1.0,
        };
        let m = r.normalised(1e-3, 0.5);
        assert_eq!(m.impacts.len(), 3);
        assert_eq!(m.impacts[0].t, 0.1);
        assert_eq!(m.impacts[0].after[0].vel.x, 3.0);
        assert_eq!(m.impacts[1].contact, Contact::Balls(1, 2));
        assert_eq!(m.impacts[2].t, 0.5);
    }
}
