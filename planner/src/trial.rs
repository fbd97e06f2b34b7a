//! One strike through the engine, exactly as `snooker simulate` would run the scene with that
//! `[cue]`, and what it did: potted or not, fouls, where the cue ball stopped, what kind of
//! pot it was, and how the object ball left its line's last contact for the pocket.

use crate::line::{Line, ShotKind};
use crate::problem::Problem;
use snooker_engine::cue::Cue;
use snooker_engine::{Event, EventKind, Motion, Shot, Vec3, simulate};

/// Why a shot is not a plan (a foul or a miss, in the snooker sense).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize)]
pub enum Fault {
    /// The cue ball hit first a ball its line does not strike first (the object ball, or a
    /// plant's first ball), or one the request does not allow.
    WrongBallFirst,
    /// The cue ball hit no ball.
    NoContact,
    /// The cue ball was potted or left the table.
    CueBallLost,
    /// The object ball was not potted in the pocket asked for.
    NotPotted,
}

/// The cue ball's way after the shot's contacts: the line (kind and the balls or cushions it
/// uses), the cushions the cue ball met after its first ball (names, in order, at most three)
/// and whether it was struck below centre (screw), near it (stun) or above (follow). Shots on
/// different routes are genuinely different shots.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Route {
    /// The line aimed.
    pub line: Line,
    /// Cushions met by the cue ball after its first ball.
    pub cushions: Vec<String>,
    /// -1 screw, 0 stun, +1 follow.
    pub spin: i8,
}

/// The object ball leaving its line's last contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Departure {
    /// When, s.
    pub t: f64,
    /// Its centre, m.
    pub pos: Vec3,
    /// Its velocity, m/s.
    pub vel: Vec3,
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
    /// The object ball just after its line's last contact (the cue ball for a direct pot,
    /// the plant's first ball, the double's last cushion, the ball kissed); None if that
    /// contact did not happen as the line has it.
    pub departure: Option<Departure>,
    /// The cue ball's route.
    pub route: Route,
    /// What the shot was, read from its events (None when the object ball was not potted).
    pub kind: Option<ShotKind>,
    /// The ball the cue ball hit first (index), if any.
    pub first_hit: Option<usize>,
}

impl Trial {
    /// True for a pot without a foul.
    pub fn pots(&self) -> bool {
        self.fault.is_none()
    }

    /// True when the object ball met nothing (cushion, jaw or ball) between the cue ball and
    /// the pocket.
    pub fn direct(&self) -> bool {
        self.kind == Some(ShotKind::Direct)
    }
}

/// Signed angle from `a` to `b` (plan), rad.
pub fn angle(a: Vec3, b: Vec3) -> f64 {
    (a.x * b.y - a.y * b.x).atan2(a.x * b.x + a.y * b.y)
}

/// The ball the cue ball `c` hit first (with two at the same instant, the first listed).
pub fn first_hit(shot: &Shot, c: usize) -> Option<(usize, &Event)> {
    let e = shot
        .events
        .iter()
        .find(|e| e.kind == EventKind::BallBall && e.balls.contains(&c))?;
    let other = e.balls.iter().copied().find(|&b| b != c)?;
    Some((other, e))
}

/// What kind of pot the object ball `o` made in `pocket`, read from the events: after the cue
/// ball `c` set it moving (directly, or through the ball it hit first: a plant), a kiss if it
/// met another ball on its way, a double if it met a cushion other than the pocket's own jaws
/// and facings, direct otherwise. None if it was not potted there.
pub fn classify(shot: &Shot, c: usize, o: usize, pocket: &str) -> Option<ShotKind> {
    let potted = shot.events.iter().find(|e| {
        e.kind == EventKind::BallPocket
            && e.balls.first() == Some(&o)
            && e.feature.as_deref() == Some(pocket)
    })?;
    let (first, _) = first_hit(shot, c)?;
    let start = shot
        .events
        .iter()
        .position(|e| e.kind == EventKind::BallBall && e.balls.contains(&o))?;
    let own = |name: &str| name.starts_with(&format!("{pocket}/"));
    let mut kind = if first == o {
        ShotKind::Direct
    } else {
        ShotKind::Plant
    };
    for e in shot.events[start + 1..]
        .iter()
        .take_while(|e| e.t < potted.t)
    {
        if !e.balls.contains(&o) {
            continue;
        }
        match e.kind {
            EventKind::BallBall => return Some(ShotKind::Kiss),
            EventKind::BallCushion
                if kind == ShotKind::Direct && !own(e.feature.as_deref().unwrap_or("")) =>
            {
                kind = ShotKind::Double;
            }
            _ => {}
        }
    }
    Some(kind)
}

impl Problem {
    /// Strikes the cue ball with `cue`, aiming `line`, and simulates the shot; None when the
    /// strike is not possible (a miscue), the shot does not simulate, or the plan is cancelled.
    pub fn trial(&self, cue: &Cue, line: &Line) -> Option<Trial> {
        let shot = self.run(cue)?;
        Some(self.judge(cue, line, &shot))
    }

    /// Strikes the cue ball with `cue` and simulates the shot, as `snooker simulate` runs the
    /// scene with that `[cue]`; None for a miscue, a shot that does not simulate, or a
    /// cancelled plan.
    pub fn run(&self, cue: &Cue) -> Option<Shot> {
        if self.cancelled() {
            return None;
        }
        let mut setup = self.setup.clone();
        setup.balls[self.cue].strike(cue, &self.setup.params).ok()?;
        self.count_shot();
        let shot = simulate(&setup, &self.options).ok();
        if shot.is_none() {
            self.count_unfinished();
        }
        shot
    }

    /// What the shot of strike `cue` did, for `line`.
    pub fn judge(&self, cue: &Cue, line: &Line, shot: &Shot) -> Trial {
        let (c, o) = (self.cue, self.object);
        let pocket = &self.setup.table.pockets[self.pocket];
        let first = first_hit(shot, c);
        let wanted = match line.kind {
            ShotKind::Plant => line.ball,
            _ => Some(o),
        };
        let mut fault = match first {
            None => Some(Fault::NoContact),
            Some((b, _)) if Some(b) != wanted || !self.may_hit_first(b) => {
                Some(Fault::WrongBallFirst)
            }
            Some(_) => None,
        };
        let contact_t = first.map_or(f64::INFINITY, |(_, e)| e.t);
        let finals = shot.final_states();
        if fault.is_none() && finals[c].motion != Motion::Stationary {
            fault = Some(Fault::CueBallLost);
        }
        let kind = classify(shot, c, o, &pocket.name);
        if fault.is_none() && kind.is_none() {
            fault = Some(Fault::NotPotted);
        }
        let departure = if fault == Some(Fault::WrongBallFirst) || first.is_none() {
            None
        } else {
            self.departure(line, shot)
        };
        let cushions = shot
            .events
            .iter()
            .filter(|e| e.t > contact_t && e.kind == EventKind::BallCushion && e.balls[0] == c)
            .filter_map(|e| e.feature.clone())
            .take(3)
            .collect();
        let third = self.setup.params.ball_radius / 3.0;
        let spin = if cue.offset[1] < -third {
            -1
        } else if cue.offset[1] > third {
            1
        } else {
            0
        };
        Trial {
            cue: *cue,
            fault,
            cue_final: finals[c].pos,
            departure,
            kind,
            first_hit: first.map(|(b, _)| b),
            route: Route {
                line: line.clone(),
                cushions,
                spin,
            },
        }
    }

    /// The object ball's state just after the last contact of `line`, if the shot made the
    /// line's contacts in its order.
    fn departure(&self, line: &Line, shot: &Shot) -> Option<Departure> {
        let o = self.object;
        let mine: Vec<&Event> = shot
            .events
            .iter()
            .filter(|e| {
                e.balls.contains(&o)
                    && matches!(e.kind, EventKind::BallBall | EventKind::BallCushion)
            })
            .collect();
        let state = |e: &Event| {
            let k = e.balls.iter().position(|&b| b == o)?;
            Some(Departure {
                t: e.t,
                pos: e.after[k].pos,
                vel: e.after[k].vel,
            })
        };
        let other = |e: &Event| e.balls.iter().copied().find(|&b| b != o);
        let first = *mine.first()?;
        match line.kind {
            ShotKind::Direct => (first.kind == EventKind::BallBall
                && other(first) == Some(self.cue))
            .then(|| state(first))?,
            ShotKind::Plant => (first.kind == EventKind::BallBall && other(first) == line.ball)
                .then(|| state(first))?,
            ShotKind::Double => {
                if !(first.kind == EventKind::BallBall && other(first) == Some(self.cue)) {
                    return None;
                }
                let names = &self.setup.table.cushions;
                let mut last = first;
                for (k, &c) in line.cushions.iter().enumerate() {
                    let e = *mine.get(k + 1)?;
                    if e.kind != EventKind::BallCushion
                        || e.feature.as_deref() != Some(names[c].name.as_str())
                    {
                        return None;
                    }
                    last = e;
                }
                state(last)
            }
            ShotKind::Kiss => {
                if !(first.kind == EventKind::BallBall && other(first) == Some(self.cue)) {
                    return None;
                }
                let e = *mine.get(1)?;
                (e.kind == EventKind::BallBall && other(e) == line.ball).then(|| state(e))?
            }
        }
    }

    /// Distance from where the trial's cue ball stopped to the target (plan), m.
    pub fn distance(&self, t: &Trial) -> f64 {
        (t.cue_final - self.target).xy().norm()
    }
}
