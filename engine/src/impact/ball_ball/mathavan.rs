//! The thesis's frictional ball-ball impact (thesis §6.1; Mathavan et al., Sports Engineering
//! 2014): friction mu_bb at the ball-ball contact with a free slip direction, the cloth's
//! reaction and friction mu_s under the ball pressed down, the other ball lifting off, and
//! energetic restitution e. Solved by [`crate::impact::impulse`].

use crate::ball::BallState;
use crate::impact::impulse::{Impact, ImpactBody, ImpactError, Kinematics, Resolution, Sample};
use crate::motion::ON_CLOTH;
use crate::params::Params;

/// The contact problem of ball `a` striking ball `b` (touching).
pub fn contact(a: &BallState, b: &BallState, p: &Params) -> Impact {
    let n = (b.pos - a.pos).normalize();
    let on = |s: &BallState| s.pos.z <= p.ball_radius + ON_CLOTH;
    Impact {
        bodies: [ImpactBody::ball(on(a)), ImpactBody::ball(on(b))],
        normal: n,
        arm: [n, -n],
        mu: p.mu_ball,
        mu_cloth: p.mu_slide,
        e: p.e_ball,
        backing: None,
    }
}

/// Solves the impact, optionally recording its progress.
pub fn solve(
    a: &BallState,
    b: &BallState,
    p: &Params,
    trace: Option<&mut Vec<Sample>>,
) -> Result<Resolution, ImpactError> {
    let k = Kinematics {
        vel: [a.vel, b.vel],
        spin: [a.spin, b.spin],
    };
    contact(a, b, p).solve(&k, p.ball_radius, p.ball_mass, trace)
}

/// States just after the impact of `a` on `b`.
pub fn resolve(
    a: &BallState,
    b: &BallState,
    p: &Params,
) -> Result<(BallState, BallState), ImpactError> {
    let out = solve(a, b, p, None)?;
    let with = |s: &BallState, i: usize| BallState {
        vel: out.after.vel[i],
        spin: out.after.spin[i],
        ..*s
    };
    Ok((with(a, 0), with(b, 1)))
}
