//! The chance of a direct pot from where the cue ball lies, in closed form: how far the
//! execution noise sends the object ball off its line, against the window the pocket leaves
//! it. Used to value positions (where the cue ball stops, for the next ball on) without
//! simulating the next stroke: cheap enough to ask for every stroke considered.
//!
//! The cue ball's direction errs by the aim's standard deviation and the squirt of the side
//! offset's (the cue model's squirt, thesis §7.1.3 and `engine::cue`). Over a distance d to
//! the contact, a heading error δ moves the cue ball's centre d·δ across its path, which turns
//! the line of centres, the object ball's direction, by d·δ / (2R cos φ) at a cut φ. The object
//! ball then misses the mouth's centre by its distance D to it times that angle; it drops while
//! that stays within the window of the pocket seen from its approach ([`window`]). The pot's
//! chance is the normal probability of that window.

use snooker_engine::table::Pocket;
use snooker_engine::{Params, Vec3};
use snooker_planner::Noise;

/// Thinnest cut counted on (rad): the engine pots a ball at 72° from close range every time,
/// at 76° five times in six, at 79° never (throw turns the object ball back: measured with
/// `player/examples/close.rs`).
pub const MAX_CUT: f64 = 75.0 * std::f64::consts::PI / 180.0;

/// The standard deviation of the cue ball's direction, rad: the aim's, and the squirt of
/// the side offset's ([`snooker_engine::cue::squirt_ratio`]), independent.
pub fn direction_sd(noise: &Noise, p: &Params) -> f64 {
    let squirt = snooker_engine::cue::squirt_ratio(noise.side, p).atan();
    noise.aim.hypot(squirt)
}

/// The window a ball approaching a pocket's mouth at angle `alpha` (rad) to the pocket's axis
/// may miss the mouth's middle by and still drop: its two half-widths (m), the narrower and
/// the wider side (a facing guides balls in on one side at a steep approach). Measured on
/// the engine ([`CORNER_WINDOW`], [`MIDDLE_WINDOW`]) and interpolated linearly in the angle;
/// none beyond the last angle measured.
pub fn window(pocket: &Pocket, alpha: f64) -> (f64, f64) {
    let table: &[(f64, f64, f64)] = if pocket.name.starts_with("middle") {
        &MIDDLE_WINDOW
    } else {
        &CORNER_WINDOW
    };
    let deg = alpha.abs().to_degrees();
    for w in table.windows(2) {
        let (a0, n0, w0) = w[0];
        let (a1, n1, w1) = w[1];
        if deg <= a1 {
            let f = ((deg - a0) / (a1 - a0)).clamp(0.0, 1.0);
            return (1e-3 * (n0 + f * (n1 - n0)), 1e-3 * (w0 + f * (w1 - w0)));
        }
    }
    (0.0, 0.0)
}

/// A corner pocket's window: (approach angle to the pocket's axis, degrees; the narrower and
/// the wider half-width, mm), measured on the engine with a ball rolling at 1.5 m/s from 0.6 m
/// (`cargo run -p snooker-player --example pocket_window`; at 0.6 and 3 m/s within 1.5 mm of
/// these but at 30°, where a slow ball drops 9 mm further on the facing's side). A ball
/// cannot approach a corner's mouth more steeply than along the cushion, 45°.
pub const CORNER_WINDOW: [(f64, f64, f64); 6] = [
    (0.0, 23.5, 23.5),
    (10.0, 22.5, 23.5),
    (20.0, 20.0, 22.0),
    (30.0, 19.5, 28.5),
    (40.0, 16.5, 44.0),
    (46.0, 0.0, 0.0),
];

/// A middle pocket's window, as [`CORNER_WINDOW`]: narrower, and closing to nothing by 60°
/// (where only balls aimed off the mouth's middle drop).
pub const MIDDLE_WINDOW: [(f64, f64, f64); 7] = [
    (0.0, 16.5, 16.5),
    (10.0, 15.5, 16.0),
    (20.0, 14.0, 14.5),
    (30.0, 11.0, 12.5),
    (40.0, 7.5, 10.0),
    (50.0, 2.5, 7.5),
    (60.0, 0.0, 0.0),
];

fn unit(v: Vec3) -> Vec3 {
    let n = v.xy().norm();
    if n > 0.0 {
        Vec3::new(v.x / n, v.y / n, 0.0)
    } else {
        Vec3::zeros()
    }
}

fn angle_between(a: Vec3, b: Vec3) -> f64 {
    (a.x * b.y - a.y * b.x).atan2(a.x * b.x + a.y * b.y).abs()
}

/// The geometry of a direct pot: the cut, the cue ball's distance to its contact, the object
/// ball's distance to the mouth and its angle of approach to the pocket's axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Direct {
    /// The cut, rad (0 full ball).
    pub cut: f64,
    /// Distance from the cue ball to the ghost ball, m.
    pub to_contact: f64,
    /// Distance from the object ball to the mouth's middle, m.
    pub to_pocket: f64,
    /// Angle between the object ball's way and the pocket's axis, rad.
    pub approach: f64,
    /// Where the cue ball's centre meets the object ball.
    pub ghost: Vec3,
}

impl Direct {
    /// The geometry of potting the ball at `ball` in `pocket` from `cue` (plan), None when
    /// the cut is thinner than [`MAX_CUT`] or the ball is behind the mouth.
    pub fn new(cue: Vec3, ball: Vec3, pocket: &Pocket, r: f64) -> Option<Direct> {
        let way = pocket.mouth - ball;
        let u = unit(way);
        let ghost = ball - 2.0 * r * u;
        let path = ghost - cue;
        let axis = unit(pocket.centre - pocket.mouth);
        let approach = angle_between(u, axis);
        if approach >= 0.5 * std::f64::consts::PI {
            return None;
        }
        let cut = angle_between(unit(path), u);
        if cut > MAX_CUT {
            return None;
        }
        Some(Direct {
            cut,
            to_contact: path.xy().norm(),
            to_pocket: way.xy().norm(),
            approach,
            ghost,
        })
    }

    /// The chance of the pot when the cue ball's direction errs with standard deviation
    /// `sd` (rad) in `pocket`.
    pub fn chance(&self, pocket: &Pocket, sd: f64, r: f64) -> f64 {
        let (narrow, wide) = window(pocket, self.approach);
        if narrow <= 0.0 {
            return 0.0;
        }
        let spread = self.to_pocket * self.to_contact * sd / (2.0 * r * self.cut.cos());
        if spread <= 0.0 {
            return 1.0;
        }
        let k = spread * std::f64::consts::SQRT_2;
        0.5 * (erf(narrow / k) + erf(wide / k))
    }
}

/// True when a ball moving from `a` to `b` passes clear of the balls at `others` (centres
/// more than two radii from the segment).
pub fn clear(a: Vec3, b: Vec3, others: &[Vec3], r: f64) -> bool {
    let d = (b - a).xy();
    let len2 = d.norm_squared();
    others.iter().all(|o| {
        let p = (o - a).xy();
        let s = if len2 > 0.0 {
            (p.dot(&d) / len2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (p - s * d).norm() >= 2.0 * r
    })
}

/// The error function (Abramowitz and Stegun 7.1.26, absolute error below 1.5e-7).
pub fn erf(x: f64) -> f64 {
    let s = x.signum();
    let x = x.abs();
    let t = 1.0 / (1.0 + 0.327_591_1 * x);
    let y = 1.0
        - (((((1.061_405_429 * t - 1.453_152_027) * t) + 1.421_413_741) * t - 0.284_496_736) * t
            + 0.254_829_592)
            * t
            * (-x * x).exp();
    s * y
}

#[cfg(test)]
mod tests {
    use super::*;
    use snooker_engine::{SnookerDims, Table};

    #[test]
    fn erf_matches_known_values() {
        for (x, want) in [
            (0.0, 0.0),
            (0.5, 0.520_499_9),
            (1.0, 0.842_700_8),
            (2.0, 0.995_322_3),
        ] {
            assert!((erf(x) - want).abs() < 2e-7, "{x}");
            assert!((erf(-x) + want).abs() < 2e-7, "{x}");
        }
    }

    #[test]
    fn shorter_and_straighter_pots_are_likelier() {
        let t = Table::snooker(&SnookerDims::default());
        let p = Params::default();
        let r = p.ball_radius;
        let pocket = t.pockets.iter().find(|p| p.name == "top-left").unwrap();
        let sd = direction_sd(&Noise::STANDARD, &p);
        let ball = Vec3::new(3.2, 1.4, 0.0);
        let line = unit(pocket.mouth - ball);
        let straight = |back: f64| {
            Direct::new(ball - back * line, ball, pocket, r)
                .unwrap()
                .chance(pocket, sd, r)
        };
        assert!(straight(0.2) > straight(0.6));
        assert!(straight(0.6) > straight(1.5));
        assert!(straight(0.2) > 0.99);
        let side = Vec3::new(-line.y, line.x, 0.0);
        let cut = Direct::new(ball - 0.6 * line + 0.4 * side, ball, pocket, r).unwrap();
        assert!(cut.cut > 0.3);
        assert!(cut.chance(pocket, sd, r) < straight(0.6));
        assert_eq!(Direct::new(ball + 0.5 * line, ball, pocket, r), None);
    }
}
