//! What a position is worth, in points, to the player who is to play it: the best direct pot
//! open to them, its chance ([`crate::chance`]) times the ball's value and what potting it
//! leads to. This is the look-ahead of one stroke: a stroke is valued by the position it
//! leaves for the next ball on (the thesis §7.3.1 asks for shots planned with the positioning
//! error taken into account; the tournament programs, PickPocket and CueCard, value a shot's
//! end state by the next shot's chance the same way).

use crate::chance::{self, Direct};
use crate::spread::Spread;
use snooker_engine::{BallKind, Params, Vec3};
use snooker_planner::{Noise, NoiseComponent};
use snooker_rules::{Colour, Frame, On};

/// How the position value counts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Valuer {
    /// Standard deviation of the cue ball's direction used for the next stroke's chance, rad.
    pub sd: f64,
    /// The execution noise the cue ball's end is spread by ([`Spread::along_path`] takes its
    /// speed, [`crate::spread::end_shifts`] all of it): the player's, each component at least
    /// the standard noise's.
    pub noise: Noise,
    /// The odds of the player's pots counted on for the rest of a break: a pot leads on to
    /// about `odds` more pots' worth of points ([`Valuer::future`]).
    pub odds: f64,
}

/// The rest of a break counted on after a pot, in pots (see [`Valuer::odds`]): a player who
/// pots nine in ten goes on for nine more on average (q / (1 - q) at q = 0.9), which is what
/// makes staying at the table worth more than the points of one ball.
pub const ODDS: f64 = 9.0;
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
            noise: at_least_standard(noise),
            odds: ODDS,
        }
    }

    /// Points a pot of a ball worth `value` leads to beyond itself in `frame`: the points
    /// still on the table after it, at most [`Valuer::odds`] pots at the average points a pot
    /// is worth from here (reds with their colours at 8, then the colours in order).
    pub fn future(&self, frame: &Frame, value: f64) -> f64 {
        let reds = frame.reds_on_table() as f64;
        let colours: Vec<Colour> = Colour::ALL
            .into_iter()
            .filter(|&c| frame.has_colour(c))
            .collect();
        let colour_points: f64 = colours.iter().map(|c| c.value() as f64).sum();
        // With a colour on after a red, that colour and then the reds with theirs.
        let (points, pots) = match frame.state().on {
            On::Closing(_) => (colour_points, colours.len() as f64),
            On::Red => (
                8.0 * reds + colour_points,
                2.0 * reds + colours.len() as f64,
            ),
            On::Colour => (
                7.0 + 8.0 * reds + colour_points,
                1.0 + 2.0 * reds + colours.len() as f64,
            ),
        };
        let left = (points - value).max(0.0);
        if pots <= 1.0 {
            return 0.0;
        }
        left.min(self.odds * points / pots)
    }

    /// The value of `frame` to the player to play it, the cue ball having stopped there, over
    /// where it stops when the stroke errs (`spread`, [`crate::spread`]): the mean of
    /// [`Valuer::from`] by three-point Gauss–Hermite along both of the spread's axes; a point
    /// where the cue ball would have run into a ball counts nothing (a cannon is not counted
    /// on). A position on a knife's edge counts for less than one the noise cannot spoil.
    pub fn robust(&self, frame: &Frame, spread: &Spread) -> f64 {
        let Some(i) = frame.cue_index() else {
            return self.position(frame);
        };
        if frame.state().ball_in_hand {
            return self.position(frame);
        }
        let at = frame.balls()[i].state.pos;
        let [u, v] = spread.axes;
        let (l, wid) = (frame.table().length, frame.table().width);
        let r = frame.params().ball_radius;
        const Z: [f64; 3] = [-1.224_744_871_391_589, 0.0, 1.224_744_871_391_589];
        const W: [f64; 3] = [1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0];
        let others: Vec<Vec3> = frame
            .balls()
            .iter()
            .enumerate()
            .filter(|&(j, _)| j != i)
            .map(|(_, b)| b.state.pos)
            .collect();
        let mut total = 0.0;
        for (&za, wa) in Z.iter().zip(W) {
            for (&zc, wc) in Z.iter().zip(W) {
                let p = at + za * spread.sd[0] * u + zc * spread.sd[1] * v;
                let p = Vec3::new(p.x.clamp(r, l - r), p.y.clamp(r, wid - r), at.z);
                let moved = za != 0.0 || zc != 0.0;
                let blocked = moved && others.iter().any(|o| (o - p).xy().norm() < 2.0 * r);
                if !blocked {
                    total += wa * wc * self.from(frame, p).0;
                }
            }
        }
        total
    }

    /// The value of `frame` to the player to play it: the best over the balls on and the
    /// pockets of the pot's chance times (the ball's value + [`Valuer::future`]); with
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
        let mut best = (0.0, None);
        for p in in_hand_points(frame) {
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
            let value = ball_value(frame, balls[b].kind);
            let worth = value + self.future(frame, value);
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

/// The places tried for the cue ball in hand: the D's grid [`IN_HAND_STEP`] apart, clear of
/// every ball; when balls cover every point of that grid, the clear place nearest the D's
/// centre (`Frame::nearest_placement`, a finer search), so that a frame with any room in the
/// D has a place (before, such a frame was "no strike can be played").
pub fn in_hand_points(frame: &Frame) -> Vec<Vec3> {
    let r = frame.params().ball_radius;
    let others = object_positions(frame);
    let grid: Vec<Vec3> = frame
        .the_d()
        .grid(IN_HAND_STEP)
        .filter(|p| others.iter().all(|o| (o - p).xy().norm() > 2.0 * r + 1e-6))
        .collect();
    if !grid.is_empty() {
        return grid;
    }
    let d = frame.the_d();
    frame
        .nearest_placement([d.centre.x, d.centre.y])
        .map(|p| vec![Vec3::new(p[0], p[1], d.centre.z)])
        .unwrap_or_default()
}

/// Where the balls of `frame` other than the cue ball are (a cue ball in hand is placed among
/// these).
pub fn object_positions(frame: &Frame) -> Vec<Vec3> {
    frame
        .balls()
        .iter()
        .filter(|b| b.kind != BallKind::Cue)
        .map(|b| b.state.pos)
        .collect()
}

/// `noise` with each component raised to at least the standard noise's.
fn at_least_standard(noise: &Noise) -> Noise {
    let mut floored = *noise;
    for c in NoiseComponent::ALL {
        floored.set(c, noise.get(c).max(Noise::STANDARD.get(c)));
    }
    floored
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
