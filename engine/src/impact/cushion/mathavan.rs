//! The thesis's frictional ball-cushion impact (thesis §6.2; Mathavan, Jackson and Parkin
//! 2010): the nose touches the ball at height h (7R/5), so the contact normal rises at theta
//! (sin theta = (h - R)/R = 2/5) towards the cushion; cushion friction mu_w with a free slip
//! direction, the cloth's reaction (dP_C = (sin theta + mu_w sin Phi cos theta) dP_I) and
//! friction mu_s, and energetic restitution e_e on the normal velocity at the nose.
//! Solved by [`crate::impact::impulse`] with the cushion as an immovable body.

use crate::ball::{BallState, Vec3};
use crate::impact::impulse::{Impact, ImpactBody, ImpactError, Kinematics, Resolution, Sample};
use crate::motion::ON_CLOTH;
use crate::params::Params;

/// The contact problem of `ball` hitting a cushion (or jaw) whose plan normal, pointing from
/// the cushion to the ball, is `normal`.
pub fn contact(ball: &BallState, normal: Vec3, p: &Params) -> Impact {
    let sin = p.cushion_sin_theta();
    let cos = (1.0 - sin * sin).sqrt();
    // From the ball's centre towards the nose: into the cushion and up.
    let n = -cos * normal + sin * Vec3::z();
    Impact {
        bodies: [
            ImpactBody::ball(ball.pos.z <= p.ball_radius + ON_CLOTH),
            ImpactBody::fixed(),
        ],
        normal: n,
        arm: [n, Vec3::zeros()],
        mu: p.mu_cushion,
        mu_cloth: p.mu_slide,
        e: p.e_cushion,
        backing: None,
    }
}

/// The contact problem of `ball`, in the air, touching a nose edge in the direction `towards`
/// (unit, from its centre to the contact). The same laws with no cloth under the ball: the
/// nose's normal impulse along `towards`, cushion friction mu_w, energetic restitution (thesis
/// §6.2's model for any contact geometry; Stronge 2000).
pub fn contact_in_air(towards: Vec3, p: &Params) -> Impact {
    Impact {
        bodies: [ImpactBody::ball(false), ImpactBody::fixed()],
        normal: towards,
        arm: [towards, Vec3::zeros()],
        mu: p.mu_cushion,
        mu_cloth: p.mu_slide,
        e: p.e_cushion,
        backing: None,
    }
}

/// State just after the impact of `ball`, in the air, on a nose edge at `towards`.
pub fn resolve_in_air(
    ball: &BallState,
    towards: Vec3,
    p: &Params,
) -> Result<BallState, ImpactError> {
    let k = Kinematics {
        vel: [ball.vel, Vec3::zeros()],
        spin: [ball.spin, Vec3::zeros()],
    };
    let out = contact_in_air(towards, p).solve(&k, p.ball_radius, p.ball_mass, None)?;
    Ok(BallState {
        vel: out.after.vel[0],
        spin: out.after.spin[0],
        ..*ball
    })
}

/// Solves the impact, optionally recording its progress.
pub fn solve(
    ball: &BallState,
    normal: Vec3,
    p: &Params,
    trace: Option<&mut Vec<Sample>>,
) -> Result<Resolution, ImpactError> {
    let k = Kinematics {
        vel: [ball.vel, Vec3::zeros()],
        spin: [ball.spin, Vec3::zeros()],
    };
    contact(ball, normal, p).solve(&k, p.ball_radius, p.ball_mass, trace)
}

/// State just after the impact.
pub fn resolve(ball: &BallState, normal: Vec3, p: &Params) -> Result<BallState, ImpactError> {
    let out = solve(ball, normal, p, None)?;
    Ok(BallState {
        vel: out.after.vel[0],
        spin: out.after.spin[0],
        ..*ball
    })
}
