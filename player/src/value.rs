//! What a position is worth, in points, to the player who is to play it: the best direct pot
//! open to them, its chance ([`crate::chance`]) times the ball's value and what potting it
//! leads to. This is the look-ahead of one stroke: a stroke is valued by the position it
//! leaves for the next ball on (the thesis §7.3.1 asks for shots planned with the positioning
//! error taken into account; the tournament programs, PickPocket and CueCard, value a shot's
//! end state by the next shot's chance the same way).

use crate::chance::{self, Direct};
use snooker_engine::{BallKind, Params, Vec3};
use snooker_planner::Noise;
use snooker_rules::{Colour, Frame, On};

/// How the position value counts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Valuer {
    /// Standard deviation of the cue ball's direction used for the next stroke's chance, rad.
    pub sd: f64,
    /// Points a pot is worth beyond the ball's own value: what potting it leads to (the next
    /// ball on and the rest of the break).
    pub continuation: f64,
}

/// Points a pot leads to beyond its own value (see [`Valuer::continuation`]): about a colour's
/// worth when in position.
pub const CONTINUATION: f64 = 4.0;
/// Spacing of the D's grid when the cue ball is in hand, m.
pub const IN_HAND_STEP: f64 = 0.05;

impl Valuer {
    /// A valuer for execution noise `noise`: the next stroke's chance is counted as if the
    /// noise were at least the standard noise (with no noise every open pot would count the
    /// same, and a position near the next ball is still the better one: the cue ball never
    /// stops exactly where it was meant to).
    pub fn new(noise: &Noise, p: &Params) -> Valuer {
        let floor = chance::direction_sd(&Noise::STANDARD, p);
        Valuer {
            sd: chance::direction_sd(noise, p).max(floor),
            continuation: CONTINUATION,
        }
    }

    /// The value of `frame` to the player to play it: the best over the balls on and the
    /// pockets of the pot's chance times (the ball's value + [`Valuer::continuation`]); with
    /// the cue ball in hand, the best place in the D. 0 when nothing is on.
    pub fn position(&self, frame: &Frame) -> f64 {
        match frame.cue_index() {
            Some(i) if !frame.state().ball_in_hand => {
                self.from(frame, frame.balls()[i].state.pos).0
            }
            _ => self.best_in_hand(frame).0,
        }
    }

    /// The best place in the D for the cue ball in hand (a grid [`IN_HAND_STEP`] apart, clear
    /// of every ball) and its value.
    pub fn best_in_hand(&self, frame: &Frame) -> (f64, Option<[f64; 2]>) {
        let r = frame.params().ball_radius;
        let others: Vec<Vec3> = frame
            .balls()
            .iter()
            .filter(|b| b.kind != BallKind::Cue)
            .map(|b| b.state.pos)
            .collect();
        let mut best = (0.0, None);
        for p in frame.the_d().grid(IN_HAND_STEP) {
            if others.iter().any(|o| (o - p).xy().norm() <= 2.0 * r + 1e-6) {
                continue;
            }
            let v = self.from(frame, p).0;
            if best.1.is_none() || v > best.0 {
                best = (v, Some([p.x, p.y]));
            }
        }
        best
    }

    /// The value of the cue ball at `cue` for the balls on in `frame`, and the (ball index,
    /// pocket index) of the best pot.
    pub fn from(&self, frame: &Frame, cue: Vec3) -> (f64, Option<(usize, usize)>) {
        let r = frame.params().ball_radius;
        let balls = frame.balls();
        let cue = Vec3::new(cue.x, cue.y, 0.0);
        let mut best = (0.0, None);
        for b in frame.balls_on() {
            let ball = balls[b].state.pos;
            let ball = Vec3::new(ball.x, ball.y, 0.0);
            let worth = ball_value(frame, balls[b].kind) + self.continuation;
            let others: Vec<Vec3> = balls
                .iter()
                .enumerate()
                .filter(|&(i, o)| i != b && o.kind != BallKind::Cue)
                .map(|(_, o)| Vec3::new(o.state.pos.x, o.state.pos.y, 0.0))
                .collect();
            for (k, pocket) in frame.table().pockets.iter().enumerate() {
                let Some(d) = Direct::new(cue, ball, pocket, r) else {
                    continue;
                };
                let c = d.chance(pocket, self.sd, r);
                if c * worth <= best.0 {
                    continue;
                }
                if chance::clear(cue, d.ghost, &others, r)
                    && chance::clear(ball, pocket.mouth, &others, r)
                {
                    best = (c * worth, Some((b, k)));
                }
            }
        }
        best
    }
}

/// The points a ball of `kind` scores when potted as the ball on in `frame` (a free ball
/// scores as the ball on).
pub fn ball_value(frame: &Frame, kind: BallKind) -> f64 {
    let s = frame.state();
    if s.free_ball && s.nominated.is_some_and(|n| n.kind() == kind) {
        return frame.value_on().unwrap_or(1) as f64;
    }
    match (kind, s.on) {
        (BallKind::Red, _) => 1.0,
        (k, On::Closing(c)) if k == c.kind() => c.value() as f64,
        (k, _) => Colour::of(k).map_or(0.0, |c| c.value() as f64),
    }
}
