//! What the cross-check compares of one engine's run, in a form both engines produce (a *shot
//! digest*, named so as not to be confused with a Rerun recording or with the engine's
//! `impulse::Contact`): the impacts in order (their *parties*: which balls, which cushion,
//! pocket, or the cloth a ball lands on; when; the velocities and spins just before and just
//! after), the slide-to-roll transitions, and where every ball ends.

use serde::Serialize;
use snooker_engine::motion::Transition;
use snooker_engine::{BallState, EventKind, Motion, Shot, Table, Vec3};

/// The parties to an impact.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Parties {
    /// Two balls, by index, the smaller first.
    Balls(usize, usize),
    /// A ball and a straight cushion nose or pocket facing (by the engine's name).
    Cushion(usize, String),
    /// A ball and a pocket jaw (by the engine's name): a curved contact.
    Jaw(usize, String),
    /// A ball falling into a pocket (by name).
    Pocket(usize, String),
    /// A ball flying over a cushion (by name) and off the table. rapier's table ends at its
    /// cushions, so only our engine reports one (no validation scene has one).
    OffTable(usize, String),
    /// An airborne ball coming down onto the cloth.
    Landing(usize),
}

impl Parties {
    /// The balls involved, in order.
    pub fn balls(&self) -> Vec<usize> {
        match self {
            Parties::Balls(a, b) => vec![*a, *b],
            Parties::Cushion(a, _)
            | Parties::Jaw(a, _)
            | Parties::Pocket(a, _)
            | Parties::OffTable(a, _)
            | Parties::Landing(a) => vec![*a],
        }
    }

    /// A short label with ball ids: "cue-red", "cue|right-baulk", "red>top-left", "cue lands".
    pub fn label(&self, ids: &[String]) -> String {
        match self {
            Parties::Balls(a, b) => format!("{}-{}", ids[*a], ids[*b]),
            Parties::Cushion(a, c) | Parties::Jaw(a, c) => format!("{}|{c}", ids[*a]),
            Parties::Pocket(a, p) => format!("{}>{p}", ids[*a]),
            Parties::OffTable(a, c) => format!("{}^{c}", ids[*a]),
            Parties::Landing(a) => format!("{} lands", ids[*a]),
        }
    }

    /// True for a ball meeting a cushion, jaw or pocket facing.
    pub fn is_cushion(&self) -> bool {
        matches!(self, Parties::Cushion(..) | Parties::Jaw(..))
    }

    /// True for a ball leaving play, into a pocket or off the table (no state after it is
    /// compared).
    pub fn is_pot(&self) -> bool {
        matches!(self, Parties::Pocket(..) | Parties::OffTable(..))
    }
}

/// Velocity and spin of one ball.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Velocities {
    /// Velocity, m/s.
    pub vel: Vec3,
    /// Angular velocity, rad/s.
    pub spin: Vec3,
}

impl From<&BallState> for Velocities {
    fn from(s: &BallState) -> Velocities {
        Velocities {
            vel: s.vel,
            spin: s.spin,
        }
    }
}

/// One impact.
#[derive(Clone, Debug, PartialEq)]
pub struct ImpactDigest {
    /// When the bodies touch, s.
    pub t: f64,
    /// Who meets whom.
    pub parties: Parties,
    /// Velocity and spin of each ball of [`Parties::balls`] just before the impact (rapier: at
    /// the start of the step in which the contact first carries an impulse).
    pub before: Vec<Velocities>,
    /// The same just after (rapier: at the end of the last step in which the contact carries
    /// an impulse; after repeats merged by [`ShotDigest::normalised`], after the last).
    pub after: Vec<Velocities>,
    /// When `after` holds, s (`t` for a single instantaneous impact).
    pub end: f64,
    /// Approach speed along the contact normal just before (plan normal for a cushion,
    /// downward speed for a landing; for a pot: the ball's plan speed), m/s.
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

/// Everything compared of one run (or one stretch of a run) of one engine.
#[derive(Clone, Debug, PartialEq)]
pub struct ShotDigest {
    /// Ball ids, in the scene's order.
    pub ids: Vec<String>,
    /// Each ball's velocity and spin at the start.
    pub start: Vec<Velocities>,
    /// Impacts in time order.
    pub impacts: Vec<ImpactDigest>,
    /// Slide-to-roll transitions in time order.
    pub rolls: Vec<Roll>,
    /// One per ball.
    pub finals: Vec<Final>,
    /// Time when every ball is at rest or pocketed, s.
    pub duration: f64,
}

impl ShotDigest {
    /// The digest of a shot of our engine on `table` (which names its jaws).
    pub fn from_shot(shot: &Shot, table: &Table) -> ShotDigest {
        let ids: Vec<String> = shot.tracks.iter().map(|t| t.id.clone()).collect();
        let mut impacts = Vec::new();
        let mut rolls = Vec::new();
        for e in &shot.events {
            let kin = |s: &[BallState], k: usize| Velocities::from(&s[k]);
            let feature = || e.feature.clone().unwrap_or_default();
            let single = |parties: Parties, approach: f64| ImpactDigest {
                t: e.t,
                parties,
                before: vec![kin(&e.before, 0)],
                after: vec![kin(&e.after, 0)],
                end: e.t,
                approach,
            };
            match e.kind {
                EventKind::BallBall => {
                    let (a, b) = (e.balls[0], e.balls[1]);
                    let (i, j) = if a < b { (0, 1) } else { (1, 0) };
                    impacts.push(ImpactDigest {
                        t: e.t,
                        parties: Parties::Balls(a.min(b), a.max(b)),
                        before: vec![kin(&e.before, i), kin(&e.before, j)],
                        after: vec![kin(&e.after, i), kin(&e.after, j)],
                        end: e.t,
                        approach: e.normal_speed.unwrap_or(0.0),
                    });
                }
                EventKind::BallCushion => {
                    let name = feature();
                    // The engine reports the feature by name; the table tells a jaw.
                    let parties = if table.jaws.iter().any(|j| j.name == name) {
                        Parties::Jaw(e.balls[0], name)
                    } else {
                        Parties::Cushion(e.balls[0], name)
                    };
                    impacts.push(single(parties, e.normal_speed.unwrap_or(0.0)));
                }
                EventKind::BallPocket => impacts.push(single(
                    Parties::Pocket(e.balls[0], feature()),
                    e.before[0].vel.xy().norm(),
                )),
                EventKind::BallOffTable => impacts.push(single(
                    Parties::OffTable(e.balls[0], feature()),
                    e.before[0].vel.norm(),
                )),
                EventKind::Transition(Transition::Landing) => {
                    impacts.push(single(Parties::Landing(e.balls[0]), -e.before[0].vel.z))
                }
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
                        slide_start: Velocities::from(&start.1),
                    });
                }
                // A lift-off repeats the state its impact left.
                EventKind::Transition(_) | EventKind::LiftOff => {}
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
        ShotDigest {
            ids,
            start: shot
                .tracks
                .iter()
                .map(|t| Velocities::from(&t.segments[0].state))
                .collect(),
            impacts,
            rolls,
            finals,
            duration: shot.duration,
        }
    }

    /// The same digest reduced to what both engines can resolve: impacts closing slower than
    /// `min_approach` dropped (resting contacts: rapier's pack contacts carry tiny impulses
    /// every step, our engine turns sustained contacts into micro-collisions at
    /// [`snooker_engine::impact::MIN_SEPARATION`]), and runs of impacts of the same parties
    /// closer than `window` seconds merged into one (the first time and state before, the last
    /// state after): a time-stepped solver cannot tell apart contacts that close within one
    /// step.
    pub fn normalised(&self, window: f64, min_approach: f64) -> ShotDigest {
        let mut impacts: Vec<ImpactDigest> = Vec::new();
        let mut last_t: Vec<(Parties, f64, usize)> = Vec::new();
        let resolved = self
            .impacts
            .iter()
            .filter(|i| i.parties.is_pot() || i.approach >= min_approach);
        for imp in resolved {
            if let Some(entry) = last_t.iter_mut().find(|(c, _, _)| *c == imp.parties) {
                if imp.t - entry.1 <= window {
                    entry.1 = imp.t;
                    impacts[entry.2].after = imp.after.clone();
                    impacts[entry.2].end = imp.end;
                    continue;
                }
                entry.1 = imp.t;
                entry.2 = impacts.len();
            } else {
                last_t.push((imp.parties.clone(), imp.t, impacts.len()));
            }
            impacts.push(imp.clone());
        }
        ShotDigest {
            impacts,
            ..self.clone()
        }
    }

    /// One stretch of a run that starts from the states `start` at `from`, s: the impacts of
    /// `impacts` (indices) after `from` (those at `from` are folded into `start`) and the
    /// slide-to-roll transitions after `from` and up to `to` (inclusive), s. A slide under way
    /// at `from` counts as starting there, from `start` (the state the other engine is given).
    pub fn stretch(
        &self,
        impacts: std::ops::Range<usize>,
        from: f64,
        to: f64,
        start: &[BallState],
    ) -> ShotDigest {
        let inside = |t: f64| t > from && t <= to;
        ShotDigest {
            ids: self.ids.clone(),
            start: start.iter().map(Velocities::from).collect(),
            impacts: self.impacts[impacts]
                .iter()
                .filter(|i| i.t > from)
                .cloned()
                .collect(),
            rolls: self
                .rolls
                .iter()
                .filter(|r| inside(r.t))
                .map(|r| {
                    if r.slide_t < from {
                        Roll {
                            slide_t: from,
                            slide_start: Velocities::from(&start[r.ball]),
                            ..*r
                        }
                    } else {
                        *r
                    }
                })
                .collect(),
            finals: self.finals.clone(),
            duration: self.duration,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn imp(t: f64, a: usize, b: usize, v: f64) -> ImpactDigest {
        let k = Velocities {
            vel: Vec3::new(v, 0.0, 0.0),
            spin: Vec3::zeros(),
        };
        ImpactDigest {
            t,
            parties: Parties::Balls(a, b),
            before: vec![k; 2],
            after: vec![k; 2],
            end: t,
            approach: 1.0,
        }
    }

    fn digest(impacts: Vec<ImpactDigest>) -> ShotDigest {
        ShotDigest {
            ids: vec!["a".into(), "b".into(), "c".into()],
            start: vec![Velocities::default(); 3],
            impacts,
            rolls: vec![],
            finals: vec![],
            duration: 1.0,
        }
    }

    #[test]
    fn normalising_joins_close_repeats_and_drops_resting_contacts() {
        let r = digest(vec![
            imp(0.1, 0, 1, 1.0),
            imp(0.10005, 1, 2, 2.0),
            imp(0.1001, 0, 1, 3.0),
            imp(0.5, 0, 1, 4.0),
            ImpactDigest {
                approach: 0.1,
                ..imp(0.7, 0, 1, 5.0)
            },
        ]);
        let m = r.normalised(1e-3, 0.5);
        assert_eq!(m.impacts.len(), 3);
        assert_eq!(m.impacts[0].t, 0.1);
        assert_eq!(m.impacts[0].end, 0.1001);
        assert_eq!(m.impacts[0].before[0].vel.x, 1.0);
        assert_eq!(m.impacts[0].after[0].vel.x, 3.0);
        assert_eq!(m.impacts[1].parties, Parties::Balls(1, 2));
        assert_eq!(m.impacts[2].t, 0.5);
    }

    #[test]
    fn a_stretch_keeps_its_own_events_and_starts_its_slides_at_its_start() {
        let mut r = digest(vec![imp(0.1, 0, 1, 1.0), imp(0.5, 0, 1, 2.0)]);
        r.rolls.push(Roll {
            ball: 1,
            t: 0.3,
            speed: 0.7,
            slide_t: 0.1,
            slide_start: r.impacts[0].after[1],
        });
        let start = vec![BallState::at_rest(0.0, 0.0, 0.02625); 3];
        let s = r.stretch(1..2, 0.2, 0.5, &start);
        assert_eq!(s.impacts.len(), 1);
        assert_eq!(s.impacts[0].t, 0.5);
        assert_eq!(s.rolls[0].slide_t, 0.2);
        assert_eq!(s.rolls[0].slide_start.vel, Vec3::zeros());
    }
}
