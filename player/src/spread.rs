//! Where the cue ball stops when the stroke errs: a normal spread about the end the stroke
//! played as meant leaves, as an ellipse on the cloth. The thesis's robot left the cue ball
//! 100–250 mm from its planned place (§7.3.1), so a position is valued over this spread
//! ([`crate::value::Valuer::robust`]), never at one point.
//!
//! Two models of the spread, chosen by [`SpreadModel`]:
//! - [`Spread::along_path`], in closed form from the speed's error alone: the run of a ball
//!   goes as its speed squared, so a run of L ends 2 L sd / v longer or shorter; across its
//!   way half that. Cheap (no simulation), used over the search's grid.
//! - [`Spread::from_shifts`], from the stroke's own sensitivities: the stroke replayed with
//!   each of the aim, speed, side and height off by one standard deviation
//!   ([`end_shifts`]), the shifts of the end summed into a covariance (first order:
//!   Σ = Σ_k d_k d_kᵀ for independent errors). It sees what the closed form misses: the
//!   spin's errors (the tip's height and side move the end by 34 and 21 mm at the standard
//!   noise against the speed's 45, docs/playing.md "Where the spread comes from") and the
//!   cushions and contacts the cue ball's way turns through. Four simulations a stroke, used
//!   in the refinement.

use snooker_engine::{Cue, Vec3};
use snooker_planner::{Noise, StrikeErrors, execute};
use snooker_rules::Frame;

/// How far one error may move the end in the sensitivities' model, m: a shift this large
/// already spoils any position, and a capped shift keeps one wild replay (a cue ball that
/// now runs round the table) from swamping the covariance.
pub const MAX_SHIFT: f64 = 0.5;

/// A normal spread on the cloth: the standard deviations along two orthogonal unit vectors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    /// The principal axes (unit plan vectors, z = 0).
    pub axes: [Vec3; 2],
    /// The standard deviation along each axis, m.
    pub sd: [f64; 2],
}

/// Which spread the search values a stroke's end over.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpreadModel {
    /// [`Spread::along_path`]: the speed's error along the cue ball's way, in closed form.
    AlongPath,
    /// [`Spread::from_shifts`] of [`end_shifts`]: the stroke replayed with each error.
    Sensitivities,
}

impl Spread {
    /// The spread of a cue ball struck at `cue_speed` (m/s, speed error `speed_sd`) that ran
    /// `path` metres after its first contact, arriving along the unit plan vector `heading`:
    /// 2 `path` `speed_sd` / `cue_speed` along its way (a ball's run goes as its speed
    /// squared), half that across it (the heading's errors, turned by each contact). A zero
    /// `heading` (the cue ball never moved after contact) gives no spread.
    pub fn along_path(cue_speed: f64, speed_sd: f64, path: f64, heading: Vec3) -> Spread {
        let along = 2.0 * path * speed_sd / cue_speed.max(1e-3);
        Spread {
            axes: [heading, Vec3::new(-heading.y, heading.x, 0.0)],
            sd: [along, 0.5 * along],
        }
    }

    /// The spread whose covariance is Σ_k d_k d_kᵀ over the plan shifts `shifts` (each the
    /// end's move under one independent error of one standard deviation): its principal axes
    /// and the square roots of its eigenvalues.
    pub fn from_shifts(shifts: &[Vec3]) -> Spread {
        let (mut a, mut b, mut c) = (0.0, 0.0, 0.0);
        for d in shifts {
            a += d.x * d.x;
            b += d.x * d.y;
            c += d.y * d.y;
        }
        let mean = 0.5 * (a + c);
        let half_gap = (0.25 * (a - c) * (a - c) + b * b).sqrt();
        let theta = 0.5 * (2.0 * b).atan2(a - c);
        Spread {
            axes: [
                Vec3::new(theta.cos(), theta.sin(), 0.0),
                Vec3::new(-theta.sin(), theta.cos(), 0.0),
            ],
            sd: [(mean + half_gap).sqrt(), (mean - half_gap).max(0.0).sqrt()],
        }
    }
}

/// How the cue ball's end `end` moves when the strike `cue` of `frame` is played with each of
/// its aim, speed, side and height off by one standard deviation of `noise` (through
/// [`execute`], as the noise samples play it): one plan shift each, at most [`MAX_SHIFT`]
/// long. A replay that pots the cue ball or cannot be struck counts as a shift of
/// [`MAX_SHIFT`] (the position is lost). The elevation's error is left out: it moved the
/// end by nothing measurable at the standard noise (docs/playing.md, "Where the spread comes
/// from").
pub fn end_shifts(frame: &Frame, cue: &Cue, end: Vec3, noise: &Noise) -> [Vec3; 4] {
    let zero = StrikeErrors {
        aim: 0.0,
        elevation: 0.0,
        speed: 0.0,
        side: 0.0,
        height: 0.0,
    };
    let errors = [
        StrikeErrors {
            aim: noise.aim,
            ..zero
        },
        StrikeErrors {
            speed: noise.speed,
            ..zero
        },
        StrikeErrors {
            side: noise.side,
            ..zero
        },
        StrikeErrors {
            height: noise.height,
            ..zero
        },
    ];
    let lost = Vec3::new(MAX_SHIFT, 0.0, 0.0);
    let Some(i) = frame.cue_index() else {
        return [lost; 4];
    };
    let ball = &frame.balls()[i].state;
    errors.map(|e| {
        let played = execute(cue, &e, ball, frame.params());
        match frame.play(&played) {
            Ok(s) if !s.verdict.cue_ball_potted => {
                let at = s.shot.tracks[i]
                    .state_at(s.shot.duration, &s.shot.params)
                    .pos;
                let d = Vec3::new(at.x - end.x, at.y - end.y, 0.0);
                let n = d.norm();
                if n > MAX_SHIFT {
                    d * (MAX_SHIFT / n)
                } else {
                    d
                }
            }
            _ => lost,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_shift_gives_its_own_axis() {
        let s = Spread::from_shifts(&[Vec3::new(0.03, 0.04, 0.0)]);
        assert!((s.sd[0] - 0.05).abs() < 1e-12);
        assert!(s.sd[1].abs() < 1e-9);
        // The major axis is the shift's direction (either sign).
        assert!((s.axes[0].x * 0.6 + s.axes[0].y * 0.8).abs() > 1.0 - 1e-12);
    }

    #[test]
    fn orthogonal_shifts_give_their_lengths() {
        let s = Spread::from_shifts(&[Vec3::new(0.0, 0.02, 0.0), Vec3::new(0.05, 0.0, 0.0)]);
        assert!((s.sd[0] - 0.05).abs() < 1e-12 && (s.sd[1] - 0.02).abs() < 1e-12);
        assert!(s.axes[0].x.abs() > 1.0 - 1e-12);
    }

    #[test]
    fn the_covariance_is_kept() {
        // Σ of the shifts equals Σ of the axes scaled by their deviations.
        let shifts = [
            Vec3::new(0.03, -0.01, 0.0),
            Vec3::new(0.02, 0.04, 0.0),
            Vec3::new(-0.01, 0.015, 0.0),
        ];
        let s = Spread::from_shifts(&shifts);
        let cov = |f: &dyn Fn(&Vec3) -> f64| shifts.iter().map(f).sum::<f64>();
        let back = |f: &dyn Fn(Vec3) -> f64| {
            (0..2)
                .map(|k| s.sd[k] * s.sd[k] * f(s.axes[k]))
                .sum::<f64>()
        };
        assert!((cov(&|d| d.x * d.x) - back(&|u| u.x * u.x)).abs() < 1e-12);
        assert!((cov(&|d| d.x * d.y) - back(&|u| u.x * u.y)).abs() < 1e-12);
        assert!((cov(&|d| d.y * d.y) - back(&|u| u.y * u.y)).abs() < 1e-12);
    }

    #[test]
    fn along_path_matches_the_run_law() {
        let s = Spread::along_path(2.0, 0.075, 1.2, Vec3::new(0.0, 1.0, 0.0));
        assert!((s.sd[0] - 2.0 * 1.2 * 0.075 / 2.0).abs() < 1e-15);
        assert!((s.sd[1] - 0.5 * s.sd[0]).abs() < 1e-15);
        assert_eq!(s.axes[1], Vec3::new(-1.0, 0.0, 0.0));
    }

    #[test]
    fn shifts_are_capped_and_vanish_without_noise() {
        // An open table's cue ball struck along the table: its shifts are finite and capped,
        // and zero for zero noise.
        let frame = Frame::open_table(15, 3);
        let i = frame.cue_index().unwrap();
        let cue = Cue {
            speed: 1.5,
            aim: 0.3,
            offset: [0.0, 0.0],
            elevation: 0.0,
        };
        let s = frame.play(&cue).unwrap();
        let end = s.shot.tracks[i]
            .state_at(s.shot.duration, &s.shot.params)
            .pos;
        let none = end_shifts(&frame, &cue, end, &Noise::STANDARD.scaled(0.0));
        assert!(none.iter().all(|d| d.norm() == 0.0));
        let some = end_shifts(&frame, &cue, end, &Noise::STANDARD);
        assert!(
            some.iter()
                .all(|d| d.norm().is_finite() && d.norm() <= MAX_SHIFT)
        );
        assert!(some.iter().any(|d| d.norm() > 0.0));
    }
}
