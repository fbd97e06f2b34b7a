//! The compliant cushion: the thesis's frictional impact (§6.2, the nose at h = 7R/5, cushion
//! and cloth friction; [`super::mathavan`]) against a cushion that gives way. Its rubber is a
//! spring of finite travel on a stiff, damped backing (the rubber is bonded to the wooden
//! rail): the work the normal impulse does in compression is stored in the rubber up to the
//! energy of its full travel, E_b = M v_b^2 / 2 (`cushion_bottom_speed`), which gives back
//! e_e^2 of it as the rigid model does; the work beyond goes into the backing, met at the speed
//! v that carries it, which gives back (1 - alpha v)^2 (Hunt and Crossley 1975, damping alpha =
//! `cushion_backing_damping`). Friction being rate-independent, the normal compliance changes
//! nothing else in impulse space (Stronge, *Impact Mechanics*, 2000, §2.3), so the impact is
//! solved by [`crate::impact::impulse`] with only its restitution changed
//! ([`crate::impact::impulse::Backing`]). Below v_b the compliant cushion is the rigid one to
//! the bit; the thesis's rigid model holds below about 2.5 m/s and its measured rebounds level
//! off above (§5.1.2, §6.2.5).

use super::mathavan;
use crate::ball::{BallState, Vec3};
use crate::impact::impulse::{Impact, ImpactError, Kinematics, Resolution, Sample};
use crate::params::Params;

/// The contact problem of `ball` hitting a compliant cushion (or jaw) whose plan normal,
/// pointing from the cushion to the ball, is `normal`.
pub fn contact(ball: &BallState, normal: Vec3, p: &Params) -> Impact {
    Impact {
        backing: Some(p.cushion_backing()),
        ..mathavan::contact(ball, normal, p)
    }
}

/// Solves the impact, optionally recording its progress.
pub fn solve(
    ball: &BallState,
    normal: Vec3,
    p: &Params,
    trace: Option<&mut Vec<Sample>>,
) -> Result<Resolution, ImpactError> {
    contact(ball, normal, p).solve(&kinematics(ball), p.ball_radius, p.ball_mass, trace)
}

/// State just after the impact.
pub fn resolve(ball: &BallState, normal: Vec3, p: &Params) -> Result<BallState, ImpactError> {
    let out = solve(ball, normal, p, None)?;
    Ok(after(ball, &out))
}

/// State just after the impact of `ball`, in the air, on a nose edge at `towards` (unit, from
/// its centre to the contact): the same laws about that normal with no cloth under the ball.
pub fn resolve_in_air(
    ball: &BallState,
    towards: Vec3,
    p: &Params,
) -> Result<BallState, ImpactError> {
    let c = Impact {
        backing: Some(p.cushion_backing()),
        ..mathavan::contact_in_air(towards, p)
    };
    let out = c.solve(&kinematics(ball), p.ball_radius, p.ball_mass, None)?;
    Ok(after(ball, &out))
}

/// The ball's and the fixed cushion's velocities before the impact.
fn kinematics(ball: &BallState) -> Kinematics {
    Kinematics {
        vel: [ball.vel, Vec3::zeros()],
        spin: [ball.spin, Vec3::zeros()],
    }
}

/// `ball` with the velocities the impact left it.
fn after(ball: &BallState, out: &Resolution) -> BallState {
    BallState {
        vel: out.after.vel[0],
        spin: out.after.spin[0],
        ..*ball
    }
}
