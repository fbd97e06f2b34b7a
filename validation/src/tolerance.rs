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
//! - A landing (a ball coming down after a hop): our engine neglects the cloth's friction
//!   percussion (thesis §6.1.6), rapier's cloth applies up to mu_s times the normal impulse,
//!   M v_z for a landing at v_z (the cloth does not bounce): the velocities after differ by
//!   mu_s v_z and the spins by 5 / (2R) times it, in both limits.
//! - The difference between the two engines' *changes* of velocity and spin at one impact
//!   ([`change_bound`], used when each stretch between impacts is compared on its own): the
//!   by-design part above, plus what the engines' slightly different incoming states explain
//!   (the normal impulse is linear in the approach speed, so an incoming velocity difference d
//!   changes it by at most (1 + e) d per unit mass, times (1 + mu) with its friction; for a
//!   ball pair twice that, both balls' differences adding up; along the tilted cushion normal
//!   divided by cos theta), plus the turn of a curved contact's normal (below), plus the
//!   cloth's friction over the time the impact spans in rapier (from the start of the step in
//!   which it begins to the end of the last step in which the contact pushes), mu_s g per second
//!   on the speed (and g for a landing) and 5 mu_s g / 2R and the sidespin rate on the spin.
//! - Cushions at the nose height under a sunk ball: rapier's ball rests `sink` lower, so it
//!   meets a nose whose contact normal is tilted by theta when its centre is sink tan(theta)
//!   nearer the nose line in plan: the impact comes up to sink tan(theta) / v_n later (v_n the
//!   plan approach speed), which matters for a grazing approach.
//! - Landings: until it touches, an airborne ball's vertical velocity changes at g, so rapier's
//!   state at the start of the landing step differs from ours at the touch by up to g dt.
//! - Curved contacts (a ball pair, a jaw; rho the distance between the centres at the touch,
//!   2R or r_j + R cos(theta) in plan): rapier takes a contact's normal from the positions at
//!   the start of the step, up to one step's relative travel before the touch, turned by up to
//!   v_t dt / rho (v_t the relative speed across the normal); and a path offset sideways by h
//!   meets the contact with its normal turned by h |v| / (rho v_n). A normal turned by phi
//!   changes the velocities after by up to k (1 + e) (v_n + v_t) phi, k = 1/2 for a ball pair
//!   (equal masses), 1 at a jaw. The sideways offset h accumulates from the velocity errors that
//!   may point anywhere, those passed on by impacts, over the travel since (a speed error from a
//!   slide's end is along the path).
//! - A final position: a ball rolling to rest from speed v with a speed error dv stops
//!   v dv / (mu_r g) further or shorter and up to (v^2 / 2 mu_r g) (dv / v) to the side; a time
//!   error t' of the start of the roll moves it by v t'.

use crate::digest::{ImpactDigest, Parties, ShotDigest};
use snooker_engine::Params;
use snooker_engine::ball::INV_INERTIA_FACTOR;

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
    /// Distance in plan between a ball's centre and a jaw's centre when they touch,
    /// r_j + R cos(theta), m.
    pub jaw_contact: f64,
    /// The scene's parameters.
    pub params: Params,
}

/// Tolerances of one impact.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ImpactTol {
    /// Time, s.
    pub t: f64,
    /// Each velocity just after, m/s (as a vector norm): the motion's share and the models'
    /// by-design difference.
    pub vel: f64,
    /// Each spin just after, rad/s (as a vector norm).
    pub spin: f64,
    /// Each velocity just before, m/s: the motion's share alone.
    pub vel_before: f64,
    /// Each spin just before, rad/s: the motion's share alone.
    pub spin_before: f64,
    /// Sideways offset of the paths meeting at the impact, m.
    pub lateral: f64,
}

/// Tolerances of one slide-to-roll transition.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RollTol {
    /// Time, s.
    pub t: f64,
    /// Speed, m/s.
    pub speed: f64,
}

/// The tolerances of every figure of one run, in the order of our engine's digest.
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

/// The velocity and spin differences the models allow by design at an impact of `parties`
/// approaching at `approach` (see the module docs).
fn model_difference(b: &Budget, parties: &Parties, approach: f64) -> (f64, f64) {
    let p = &b.params;
    let dv = match parties {
        // Thesis §6.1.6: the landing's friction percussion is neglected in our engine; rapier's
        // cloth gives up to mu_s times the normal impulse M v_z (no bounce), whatever the models.
        Parties::Landing(_) => p.mu_slide * approach,
        _ if !b.friction => 0.0,
        // Equal masses: the normal impulse per unit mass is (1 + e) v_n / 2 per ball.
        Parties::Balls(..) => {
            2.0 * p.mu_ball * (1.0 + p.e_ball) * approach / 2.0 * (1.0 + p.mu_slide)
        }
        // Impulse along the tilted normal (1 + e) v_n / cos(theta), friction mu_w of it at
        // the nose and mu_s of its vertical part at the cloth.
        Parties::Cushion(..) | Parties::Jaw(..) => {
            let s = p.cushion_sin_theta();
            2.0 * (p.mu_cushion + p.mu_slide * s) * (1.0 + p.e_cushion) * approach
                / (1.0 - s * s).sqrt()
        }
        Parties::Pocket(..) | Parties::OffTable(..) => 0.0,
    };
    (dv, INV_INERTIA_FACTOR * dv / p.ball_radius)
}

/// Gain from an incoming velocity difference (the largest over the balls) to the difference
/// of the velocity changes at an impact of `parties` (see the module docs).
fn incoming_gain(b: &Budget, parties: &Parties) -> f64 {
    let p = &b.params;
    let mu = |m: f64| if b.friction { m } else { 0.0 };
    match parties {
        Parties::Balls(..) => (1.0 + p.e_ball) * (1.0 + mu(p.mu_ball)) * (1.0 + p.mu_slide),
        Parties::Cushion(..) | Parties::Jaw(..) => {
            let s = p.cushion_sin_theta();
            (1.0 + p.e_cushion) * (1.0 + mu(p.mu_cushion) + p.mu_slide * s) / (1.0 - s * s).sqrt()
        }
        Parties::Landing(_) => 1.0 + p.mu_slide,
        Parties::Pocket(..) | Parties::OffTable(..) => 0.0,
    }
}

/// At a curved contact (a ball pair, a jaw), how far the velocities after may move when the
/// normal is taken at the start of rapier's step and the paths are offset sideways by
/// `lateral` (see the module docs), m/s; zero elsewhere.
fn curvature(b: &Budget, imp: &ImpactDigest, lateral: f64) -> f64 {
    let p = &b.params;
    let plan = |v: snooker_engine::Vec3| v.xy().norm();
    let (rho, k, rel) = match &imp.parties {
        Parties::Balls(..) => (
            2.0 * p.ball_radius,
            0.5 * (1.0 + p.e_ball),
            plan(imp.before[0].vel - imp.before[1].vel),
        ),
        Parties::Jaw(..) => (b.jaw_contact, 1.0 + p.e_cushion, plan(imp.before[0].vel)),
        Parties::Cushion(..)
        | Parties::Pocket(..)
        | Parties::OffTable(..)
        | Parties::Landing(_) => {
            return 0.0;
        }
    };
    let vn = imp.approach.clamp(0.0, rel);
    let vt = (rel * rel - vn * vn).sqrt();
    // A normal cannot turn by more than a right angle and still be met.
    let phi =
        (vt * b.dt / rho + lateral * rel / (rho * vn.max(1e-12))).min(std::f64::consts::FRAC_PI_2);
    k * (vn + vt) * phi
}

/// How fast a ball's velocity changes on its way into an impact of `parties`, m/s^2: the
/// cloth's friction, and for a landing gravity as well.
fn approach_accel(p: &Params, parties: &Parties) -> f64 {
    let a_s = p.mu_slide * p.g;
    match parties {
        Parties::Landing(_) => a_s + p.g,
        _ => a_s,
    }
}

/// How much later rapier's sunk ball meets a nose at 7R/5 (see the module docs), s.
fn nose_delay(b: &Budget, parties: &Parties, approach: f64) -> f64 {
    if b.level_cushions || !parties.is_cushion() {
        return 0.0;
    }
    let s = b.params.cushion_sin_theta();
    b.sink * s / (1.0 - s * s).sqrt() / approach.max(1e-12)
}

/// Bound of the difference between the two engines' changes of velocity and of spin at one
/// impact (m/s, rad/s): `ours` and `rapier` are the same impact in each engine, `incoming` the
/// largest difference of the balls' velocities just before it (measured, m/s), `lateral` the
/// sideways offset of the paths there ([`ImpactTol::lateral`]).
pub fn change_bound(
    b: &Budget,
    ours: &ImpactDigest,
    rapier: &ImpactDigest,
    incoming: f64,
    lateral: f64,
) -> (f64, f64) {
    let p = &b.params;
    let (mv, mw) = model_difference(b, &ours.parties, ours.approach);
    let tilt_v = if ours.parties.is_cushion() {
        tilt(b, ours.approach)
    } else {
        0.0
    };
    // rapier's state before is up to one step before the touch, its state after at the end of
    // the contact's last step; ours may span merged repeats.
    let span = (rapier.end - rapier.t + b.dt) + (ours.end - ours.t);
    let a_s = p.mu_slide * p.g;
    let a_in = approach_accel(p, &ours.parties);
    let coupled = incoming_gain(b, &ours.parties) * incoming + curvature(b, ours, lateral);
    let dv = mv + tilt_v + coupled + a_in * span;
    let dw =
        mw + INV_INERTIA_FACTOR / p.ball_radius * (coupled + a_s * span) + p.sidespin_decel * span;
    (dv, dw)
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

/// Derives the tolerances of every figure from our engine's digest `ours` of a whole run (see
/// module docs).
pub fn allowances(ours: &ShotDigest, b: &Budget) -> Allowances {
    allowances_from(ours, b, 0.0)
}

/// The tolerances of a stretch of a run that starts at `t0` from the same state in both
/// engines: the bounds accumulate from zero there.
pub fn allowances_from(ours: &ShotDigest, b: &Budget, t0: f64) -> Allowances {
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
    // Accumulated bounds: speed error, time error, time of the last event; velocity error that
    // may point anywhere (passed on by impacts) and the sideways offset it has built up.
    let (mut dv, mut dt_acc, mut t_last) = (0.0f64, 0.0f64, t0);
    let (mut dv_any, mut lateral) = (0.0f64, 0.0f64);
    // Per ball: (speed when it last started a roll or left an impact, dv then, time error then),
    // from its speed at the start.
    let mut last_motion: Vec<(f64, f64, f64)> = ours
        .start
        .iter()
        .map(|s| (s.vel.xy().norm(), 0.0, 0.0))
        .collect();
    // Per ball: since when it may have been sliding (every ball may slide from the start).
    let mut sliding_since: Vec<Option<f64>> = vec![Some(t0); ours.ids.len()];
    for (t, is_roll, i) in order {
        lateral += dv_any * (t - t_last);
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
            let tol_t = dt_acc
                + b.dt
                + (t - t_last) * dv / speed
                + nose_delay(b, &imp.parties, imp.approach);
            let (mv, mw) = model_difference(b, &imp.parties, imp.approach);
            let dv_here = dv + a_s * (tol_t + b.dt);
            let a_in = approach_accel(p, &imp.parties);
            let tilt_v = if imp.parties.is_cushion() {
                tilt(b, imp.approach)
            } else {
                0.0
            };
            let tol_v = dv_here + mv + tilt_v + curvature(b, imp, lateral);
            let slid = imp
                .parties
                .balls()
                .iter()
                .filter_map(|&ball| sliding_since[ball].map(|t0| t - t0))
                .fold(0.0, f64::max);
            let tol_w_before =
                dv_here / r + INV_INERTIA_FACTOR * a_s / r * (tol_t + b.dt + eps * slid);
            let tol_w = tol_w_before + mw;
            out.impacts[i] = ImpactTol {
                t: tol_t,
                vel: tol_v,
                spin: tol_w,
                vel_before: dv + a_in * (tol_t + b.dt),
                spin_before: tol_w_before,
                lateral,
            };
            dv = dv.max(tol_v);
            dv_any = dv_any.max(tol_v);
            dt_acc = dt_acc.max(tol_t);
            for (&ball, after) in imp.parties.balls().iter().zip(&imp.after) {
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
    use crate::digest::{Roll, Velocities};
    use snooker_engine::Vec3;

    #[test]
    fn a_stun_allows_the_sink_shift_of_the_rolling_speed() {
        let p = Params::default();
        let v0 = 2.0;
        let t = 2.0 * v0 / (7.0 * p.mu_slide * p.g);
        let ours = ShotDigest {
            ids: vec!["cue".into()],
            start: vec![Velocities::default()],
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
            jaw_contact: 0.034,
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
