//! How far apart the two engines' figures may be, derived event by event from the known
//! differences between the runs (docs/validation.md explains each term):
//!
//! - Time step dt: rapier resolves every discrete change (an impact, the start of rolling, a
//!   pot) at a step boundary, so each can shift by up to one step; between two steps the cloth's
//!   friction changes a speed by up to mu_s g dt.
//! - Soft contact: a resting ball sinks `sink` into rapier's cloth and rapier puts the contact
//!   point at mid-depth, so the ball rolls on a radius R' = R (1 - eps), eps = sink / 2R.
//!   From the conservation of angular momentum about the contact point during a slide, the
//!   rolling speed (k^2 v0 + 0.4 k w0 R) / (k^2 + 0.4), k = R'/R, moves by at most
//!   eps (0.41 |v0| + 0.13 |w0| R); the sliding time |v0 - k w0 R| / ((1 + 2.5 k^2) mu_s g) by at
//!   most eps (|w0| R / (3.5 mu_s g) + 1.43 t_slide); while it slides the friction's torque arm is
//!   R' too, so its spin changes at (5 mu_s g / 2R)(1 - eps) and after sliding for tau it is off
//!   by up to eps (5 mu_s g / 2R) tau.
//! - A speed error dv carried over a stretch of travel of duration tau, arriving at speed v,
//!   shifts the arrival by at most tau dv / v (the motion decelerates, so v is its slowest).
//! - An impact maps velocity errors into velocity errors with gain at most 1 (Newton's law for
//!   equal masses); a time shift dt' adds mu_s g dt' (the deceleration before it).
//! - With the cushions level in the frictionless limit, the sunk ball meets them slightly below
//!   their axis: the normal tilts by sink / (R + r_c), giving a vertical velocity of up to
//!   (1 + e) v_n sink / (R + r_c).
//! - With friction on, the models differ by design (Newton vs energetic restitution, Coulomb
//!   friction resolved once per time step vs integrated over the normal impulse): each engine's
//!   friction impulse is at most mu times the normal impulse, so the velocities after the
//!   impact differ by at most twice that, 2 mu (1 + e) v_n (plus the cloth's mu_s share), and the
//!   spins by 5 / (2R) times it; that difference is carried forward like any other.
//! - A final position: a ball rolling to rest from speed v with a speed error dv stops
//!   v dv / (mu_r g) further or shorter and up to (v^2 / 2 mu_r g) (dv / v) to the side; a time
//!   error t' of the start of the roll moves it by v t'.

use crate::record::Record;
use snooker_engine::Params;

/// What sets the tolerances of one comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    /// rapier's time step, s.
    pub dt: f64,
    /// Depth the resting balls sank into rapier's cloth, m.
    pub sink: f64,
    /// True when the impacts have friction (models differing by design).
    pub friction: bool,
    /// True when rapier's cushions touch level with the ball's centre.
    pub level_cushions: bool,
    /// Radius of the capsules standing for the cushion noses, m.
    pub nose_radius: f64,
    /// The scene's parameters.
    pub params: Params,
}

/// Tolerances of one impact.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ImpactTol {
    /// Time, s.
    pub t: f64,
    /// Each velocity component just after, m/s (as a vector norm).
    pub vel: f64,
    /// Each spin just after, rad/s (as a vector norm).
    pub spin: f64,
}

/// Tolerances of one slide-to-roll transition.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RollTol {
    /// Time, s.
    pub t: f64,
    /// Speed, m/s.
    pub speed: f64,
}

/// The tolerances of every figure of one run, in the order of our engine's record.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Allowances {
    /// One per impact.
    pub impacts: Vec<ImpactTol>,
    /// One per slide-to-roll transition.
    pub rolls: Vec<RollTol>,
    /// One per ball: the plan distance between the final positions, m.
    pub finals: Vec<f64>,
}

/// Speed error bound of a slide from (v0, w0) on a radius off by `eps` (see the module docs).
fn sink_speed(eps: f64, v0: f64, w0r: f64) -> f64 {
    eps * (0.41 * v0 + 0.13 * w0r)
}

/// Sliding-time error bound of a slide lasting `t_slide` (see the module docs).
fn sink_time(eps: f64, w0r: f64, a_slide: f64, t_slide: f64) -> f64 {
    eps * (w0r / (3.5 * a_slide) + 1.43 * t_slide)
}

/// The velocity and spin differences the models allow by design at an impact with friction.
fn model_difference(b: &Budget, ball_ball: bool, approach: f64) -> (f64, f64) {
    let p = &b.params;
    if !b.friction {
        return (0.0, 0.0);
    }
    let s = p.cushion_sin_theta();
    let per_mass = if ball_ball {
        // Equal masses: the normal impulse per unit mass is (1 + e) v_n / 2 per ball.
        p.mu_ball * (1.0 + p.e_ball) * approach / 2.0 * (1.0 + p.mu_slide)
    } else {
        // Impulse along the tilted normal (1 + e) v_n / cos(theta), friction mu_w of it at
        // the nose and mu_s of its vertical part at the cloth.
        (p.mu_cushion + p.mu_slide * s) * (1.0 + p.e_cushion) * approach / (1.0 - s * s).sqrt()
    };
    let dv = 2.0 * per_mass;
    (dv, 2.5 * dv / p.ball_radius)
}

/// Vertical velocity from the tilt of a level cushion's normal under a sunk ball.
fn tilt(b: &Budget, approach: f64) -> f64 {
    if b.level_cushions {
        let r = b.params.ball_radius;
        (1.0 + b.params.e_cushion) * approach * b.sink / (r + b.nose_radius)
    } else {
        0.0
    }
}

/// Derives the tolerances of every figure from our engine's record `ours` (see module docs).
pub fn allowances(ours: &Record, b: &Budget) -> Allowances {
    let p = &b.params;
    let r = p.ball_radius;
    let a_s = p.mu_slide * p.g;
    let a_r = p.mu_roll * p.g;
    let eps = b.sink / (2.0 * r);
    // Events in time order: impacts (false) and rolls (true), by index.
    let mut order: Vec<(f64, bool, usize)> = ours
        .impacts
        .iter()
        .enumerate()
        .map(|(i, e)| (e.t, false, i))
        .chain(ours.rolls.iter().enumerate().map(|(i, e)| (e.t, true, i)))
        .collect();
    order.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut out = Allowances {
        impacts: vec![ImpactTol::default(); ours.impacts.len()],
        rolls: vec![RollTol::default(); ours.rolls.len()],
        finals: vec![0.0; ours.ids.len()],
    };
    // Accumulated bounds: speed error, time error, time of the last event.
    let (mut dv, mut dt_acc, mut t_last) = (0.0f64, 0.0f64, 0.0f64);
    // Per ball: (speed when it last started a roll or left an impact, dv then, time error then).
    let mut last_motion = vec![(0.0f64, 0.0f64, 0.0f64); ours.ids.len()];
    // Per ball: since when it may have been sliding (every ball may slide from the start).
    let mut sliding_since: Vec<Option<f64>> = vec![Some(0.0); ours.ids.len()];
    for (t, is_roll, i) in order {
        if is_roll {
            let roll = &ours.rolls[i];
            let v0 = roll.slide_start.vel.xy().norm();
            let w0r = roll.slide_start.spin.xy().norm() * r;
            let tol_t = dt_acc
                + b.dt
                + sink_time(eps, w0r, a_s, roll.t - roll.slide_t)
                + 2.0 * dv / (3.5 * a_s);
            let tol_v = dv + sink_speed(eps, v0, w0r) + a_s * b.dt;
            out.rolls[i] = RollTol {
                t: tol_t,
                speed: tol_v,
            };
            dv = dv.max(tol_v);
            dt_acc = dt_acc.max(tol_t);
            last_motion[roll.ball] = (roll.speed, tol_v, tol_t);
            sliding_since[roll.ball] = None;
        } else {
            let imp = &ours.impacts[i];
            let speed = imp.approach.max(a_s * b.dt);
            let tol_t = dt_acc + b.dt + (t - t_last) * dv / speed;
            let ball_ball = imp.contact.balls().len() == 2;
            let (mv, mw) = model_difference(b, ball_ball, imp.approach);
            let dv_here = dv + a_s * (tol_t + b.dt);
            let tilt_v = if ball_ball {
                0.0
            } else {
                tilt(b, imp.approach)
            };
            let tol_v = dv_here + mv + tilt_v;
            let slid = imp
                .contact
                .balls()
                .iter()
                .filter_map(|&ball| sliding_since[ball].map(|t0| t - t0))
                .fold(0.0, f64::max);
            let tol_w = dv_here / r + 2.5 * a_s / r * (tol_t + b.dt + eps * slid) + mw;
            out.impacts[i] = ImpactTol {
                t: tol_t,
                vel: tol_v,
                spin: tol_w,
            };
            dv = dv.max(tol_v);
            dt_acc = dt_acc.max(tol_t);
            for (&ball, after) in imp.contact.balls().iter().zip(&imp.after) {
                last_motion[ball] = (after.vel.xy().norm(), tol_v, tol_t);
                sliding_since[ball] = Some(t);
            }
        }
        t_last = t;
    }
    for (i, f) in out.finals.iter_mut().enumerate() {
        let (v, dv_f, dt_f) = last_motion[i];
        // 1e-6 m: a ball that never moves (or barely does) is compared to the micrometre.
        *f = 1.5 * v * dv_f / a_r + v * (dt_f + b.dt) + 1e-6;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::record::{Roll, Velocities};
    use snooker_engine::Vec3;

    #[test]
    fn a_stun_allows_the_sink_shift_of_the_rolling_speed() {
        let p = Params::default();
        let v0 = 2.0;
        let t = 2.0 * v0 / (7.0 * p.mu_slide * p.g);
        let ours = Record {
            ids: vec!["cue".into()],
            impacts: vec![],
            rolls: vec![Roll {
                ball: 0,
                t,
                speed: 5.0 / 7.0 * v0,
                slide_t: 0.0,
                slide_start: Velocities {
                    vel: Vec3::new(v0, 0.0, 0.0),
                    spin: Vec3::zeros(),
                },
            }],
            finals: vec![],
            duration: 10.0,
        };
        let b = Budget {
            dt: 1e-4,
            sink: 6.6e-5,
            friction: false,
            level_cushions: true,
            nose_radius: 0.0078,
            params: p,
        };
        let a = allowances(&ours, &b);
        let eps = 6.6e-5 / (2.0 * p.ball_radius);
        // The rolling speed moves by d/dk at k = 1 of (k^2 v0)/(k^2 + 0.4) times eps: 0.408 v0 eps.
        assert!(a.rolls[0].speed >= 0.408 * v0 * eps);
        assert!(a.rolls[0].speed < 0.408 * v0 * eps + 3.0 * p.mu_slide * p.g * 1e-4);
        assert!(a.rolls[0].t >= 1.43 * eps * t + 1e-4);
    }
}
