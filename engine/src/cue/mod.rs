//! The cue strike (thesis §2.4.1, §7.1.2, §7.1.3).
//!
//! Geometry (thesis eqs. 7.4-7.6): the cue's axis runs along the heading `aim`, inclined
//! down by `elevation`, and passes through the point `offset` = [side, height] of the vertical
//! plane through the ball's centre perpendicular to the heading (side positive to the right of
//! the heading, height positive up). The tip is a sphere of radius r on that axis; it first
//! touches the ball where the axis point is R + r from the centre, and the contact point lies
//! on the line from the ball's centre to the tip's centre. (The thesis measures its offsets
//! x'_0, y'_0 in the plane tangent to the ball at the back: x'_0 = side,
//! y'_0 = height + R tan(elevation).)
//!
//! Dynamics: the chalked tip grips the ball, so the impulse acts along the cue's axis at the
//! contact point (thesis §7.1.3 after Cross 2008). Its size follows from a collinear impact of
//! the cue (mass `cue_mass`) with the ball's effective mass at the contact point, with the tip's
//! restitution (fitted to the measured 1.45 speed ratio, thesis §5.1.4). The cloth takes the
//! downward part of the impulse through the ball's bottom point (no moment) and its friction
//! percussion is neglected, as in the thesis (about 2% of the cue force at 6.5 deg), unless
//! `mu_strike_cloth` is set: then the cloth's friction acts during the strike ([`cloth`],
//! de la Torre Juarez 1994). The bed stops the ball's downward motion; with the bed's
//! restitution `e_bed` set it gives e_bed of it back upwards and the ball jumps
//! ([`crate::motion::bed`]; off by default, as in the thesis).
//! Squirt: the tip's transverse end mass lets the ball leave off the axis, away from the side
//! struck (Shepard 1997, Cross 2008): tan(squirt) = 2.5 s c / (1 + 2.5 c^2 + M / m_e), with
//! s = b/R the contact's side offset and c = sqrt(1 - s^2).

pub mod cloth;

use crate::ball::{Ball, BallState, INV_INERTIA_FACTOR, Vec3};
use crate::motion;
use crate::params::Params;
use crate::shown::Shown;
use crate::sim::setup::{MAX_BALL_SPEED, MAX_SPIN_SPEED};
use serde::{Deserialize, Serialize};

/// Fastest cue speed accepted, m/s (the fastest human breaks reach about 10 m/s).
pub const MAX_CUE_SPEED: f64 = 15.0;
/// Largest |aim| accepted, rad: one turn either way covers every heading.
pub const MAX_AIM: f64 = std::f64::consts::TAU;
/// Steepest cue accepted, rad (a vertical cue has no heading).
pub const MAX_ELEVATION: f64 = 89.0 * std::f64::consts::PI / 180.0;

/// A cue strike, as in a scene file's `[cue]` table.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cue {
    /// Cue speed at impact, m/s.
    pub speed: f64,
    /// Heading of the cue in the table frame, rad (0 = +x).
    pub aim: f64,
    /// Offset of the cue's axis from the ball's centre, [side (right +), height (up +)], m.
    pub offset: [f64; 2],
    /// Inclination of the cue to the horizontal, rad (positive = butt raised).
    pub elevation: f64,
}

/// What a strike did.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Strike {
    /// The ball's state just after the strike.
    pub state: BallState,
    /// Contact point relative to the ball's centre, m.
    pub contact: Vec3,
    /// Distance of the contact point from the cue's axis through the centre, m.
    pub contact_offset: f64,
    /// Angle between the ball's new horizontal velocity and the cue's heading, rad
    /// (positive = to the left of the heading).
    pub squirt: f64,
    /// Horizontal speed given to the ball / cue speed.
    pub speed_ratio: f64,
    /// The cloth's friction impulse during the strike, N s (horizontal; zero unless
    /// `mu_strike_cloth` is set and the cue is inclined: [`cloth`]).
    pub cloth_friction: Vec3,
}

/// Why a strike cannot be played.
#[derive(Clone, Debug, PartialEq)]
pub struct CueError {
    /// The `[cue]` key at fault; "params" or "ball" when the parameters or the struck ball's
    /// state given to [`strike`] are at fault instead.
    pub key: &'static str,
    /// Why.
    pub reason: String,
}

impl std::fmt::Display for CueError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.key, self.reason)
    }
}

impl std::error::Error for CueError {}

fn err(key: &'static str, reason: String) -> CueError {
    CueError { key, reason }
}

/// A length for a message: in millimetres, or in metres with an exponent when large.
fn length_text(metres: f64) -> String {
    if metres < 10.0 {
        format!("{:.1} mm", metres * 1e3)
    } else {
        format!("{metres:.3e} m")
    }
}

/// tan(squirt) / 1 for a contact whose side offset is `b` (signed), from the gripping-tip
/// model with end mass `m_e` (see the module docs); the sign follows the offset.
pub fn squirt_ratio(b: f64, p: &Params) -> f64 {
    let s = (b / p.ball_radius).clamp(-1.0, 1.0);
    let c2 = 1.0 - s * s;
    INV_INERTIA_FACTOR * s * c2.sqrt()
        / (1.0 + INV_INERTIA_FACTOR * c2 + p.ball_mass / p.cue_endmass)
}

impl Ball {
    /// Strikes this ball with `cue` ([`strike`]): its state becomes the struck one; returns
    /// what the strike did. On an error the ball is left as it was.
    pub fn strike(&mut self, cue: &Cue, p: &Params) -> Result<Strike, CueError> {
        let s = strike(&self.state, cue, p)?;
        self.state = s.state;
        Ok(s)
    }
}

/// Strikes `ball` with `cue`; the impulse adds to whatever motion the ball had.
pub fn strike(ball: &BallState, cue: &Cue, p: &Params) -> Result<Strike, CueError> {
    let finite = |key: &'static str, v: f64| {
        if v.is_finite() {
            Ok(())
        } else {
            Err(err(key, format!("must be a finite number, got {v}")))
        }
    };
    // A caller's own parameters and ball are checked too: a scene's were checked as it was
    // read, but a strike built in code would otherwise turn a NaN into the ball's motion.
    if let Err(e) = p.validate() {
        return Err(err("params", format!("{}: {}", e.name, e.reason)));
    }
    let state_finite = [ball.pos, ball.vel, ball.spin]
        .iter()
        .all(|v| v.iter().all(|x| x.is_finite()));
    if !state_finite {
        return Err(err(
            "ball",
            "the struck ball's position, velocity and spin must be finite".into(),
        ));
    }
    finite("speed", cue.speed)?;
    finite("aim", cue.aim)?;
    finite("offset", cue.offset[0])?;
    finite("offset", cue.offset[1])?;
    finite("elevation", cue.elevation)?;
    if cue.speed <= 0.0 || cue.speed > MAX_CUE_SPEED {
        return Err(err(
            "speed",
            format!(
                "cue speed must lie in (0, {MAX_CUE_SPEED}] m/s, got {}",
                Shown(cue.speed)
            ),
        ));
    }
    if cue.aim.abs() > MAX_AIM {
        return Err(err(
            "aim",
            format!(
                "a heading must lie in [-2 pi, 2 pi] rad, got {}",
                Shown(cue.aim)
            ),
        ));
    }
    if !(0.0..=MAX_ELEVATION).contains(&cue.elevation) {
        return Err(err(
            "elevation",
            format!(
                "must lie in [0, {:.4}] rad (0 to 89 deg), got {}",
                MAX_ELEVATION,
                Shown(cue.elevation)
            ),
        ));
    }
    let (r, tip) = (p.ball_radius, p.cue_tip_radius);
    let heading = Vec3::new(cue.aim.cos(), cue.aim.sin(), 0.0);
    let side = heading.cross(&Vec3::z());
    let (sin_e, cos_e) = cue.elevation.sin_cos();
    let dir = cos_e * heading - sin_e * Vec3::z();
    // The axis's distance from the ball's centre: `offset` lies in the vertical plane across
    // the heading, which a cue inclined by `elevation` crosses obliquely, so the height part is
    // foreshortened by cos(elevation) (a steep cue's axis passes near the centre for a large
    // height offset). The tip reaches the ball only if it is within R + r.
    let miss = cue.offset[0].hypot(cue.offset[1] * cos_e);
    if miss > r + tip {
        return Err(err(
            "offset",
            format!(
                "the cue's axis passes {} from the ball's centre and misses it (limit {:.1} mm)",
                length_text(miss),
                (r + tip) * 1e3
            ),
        ));
    }
    let o = cue.offset[0] * side + cue.offset[1] * Vec3::z();

    // Tip centre on the axis at R + r from the ball's centre, on the cue's side (thesis eq. 7.5);
    // the axis is within R + r of the centre, so the root is real but for rounding.
    let od = o.dot(&dir);
    let disc = (od * od - o.norm_squared() + (r + tip) * (r + tip)).max(0.0);
    let tip_centre = o - (od + disc.sqrt()) * dir;
    if p.ball_radius + tip_centre.z < tip {
        return Err(err(
            "offset",
            "the cue tip would have to go through the cloth to reach that point".into(),
        ));
    }
    let n = tip_centre.normalize();
    let contact = r * n;
    let along = contact.dot(&dir);
    let contact_offset = (contact - along * dir).norm();
    if contact_offset > p.miscue_limit * r {
        return Err(err(
            "offset",
            format!(
                "miscue: the tip meets the ball {:.1} mm off centre (across the cue's line through \
                 the centre), beyond the limit of {} R = {:.1} mm (thesis eq. 7.7)",
                contact_offset * 1e3,
                p.miscue_limit,
                p.miscue_limit * r * 1e3
            ),
        ));
    }

    // Axial impulse: collinear impact of the cue with the ball's effective mass at the contact,
    // the cloth blocking vertical motion (1/m_eff = cos^2(elev)/M + |c x d|^2 / I).
    let inertia = p.inertia();
    let inv_m_eff = cos_e * cos_e / p.ball_mass + contact.cross(&dir).norm_squared() / inertia;
    let m_eff = 1.0 / inv_m_eff;
    let j_axial =
        (1.0 + p.cue_tip_restitution) * cue.speed * p.cue_mass * m_eff / (p.cue_mass + m_eff);
    // Squirt: transverse impulse away from the side struck.
    let b_side = contact.dot(&side);
    let j_side = -squirt_ratio(b_side, p) * j_axial * cos_e;
    let impulse = j_axial * dir + j_side * side;

    let mut out = *ball;
    out.vel += Vec3::new(impulse.x, impulse.y, 0.0) / p.ball_mass;
    out.spin += contact.cross(&impulse) / inertia;
    // The cloth's normal impulse is the downward part of the cue's.
    let normal = -impulse.z;
    let mut friction = cloth::percussion(ball, &out, normal, p);
    if let Some(f) = friction {
        out = cloth::apply(&out, f, p);
    }
    // The bed gives back e_bed of what it stopped (motion/bed.rs): the ball jumps, and the
    // cloth's friction acts on through that impulse too, the cue's part done (a = 0).
    let jump = motion::bed::rebound(normal.max(0.0) / p.ball_mass, p);
    if jump > 0.0 {
        out.vel.z = jump;
        if let Some(f) = cloth::percussion(&out, &out, p.ball_mass * jump, p) {
            out = cloth::apply(&out, f, p);
            friction = Some(friction.unwrap_or_else(Vec3::zeros) + f);
        }
    }
    // The strike's result must be a ball the engine takes (a heavy cue at the top speed
    // gives more): blamed on the cue speed, the input that made it.
    let (speed, surface) = (out.vel.norm(), out.spin.norm() * r);
    if speed > MAX_BALL_SPEED || surface > MAX_SPIN_SPEED {
        return Err(err(
            "speed",
            format!(
                "the strike gives the ball {speed:.1} m/s and a spin surface speed of \
                 {surface:.1} m/s, beyond any shot (at most {MAX_BALL_SPEED} and \
                 {MAX_SPIN_SPEED} m/s): strike more slowly or with a lighter cue"
            ),
        ));
    }
    let out = motion::settle(out, p);
    let mut dv = Vec3::new(impulse.x, impulse.y, 0.0) / p.ball_mass;
    if let Some(f) = friction {
        dv += f / p.ball_mass;
    }
    let squirt = heading.cross(&dv).z.atan2(heading.dot(&dv));
    Ok(Strike {
        state: out,
        contact,
        contact_offset,
        squirt,
        speed_ratio: dv.norm() / cue.speed,
        cloth_friction: friction.unwrap_or_else(Vec3::zeros),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Motion;

    fn hit(offset: [f64; 2], elevation: f64) -> Result<Strike, CueError> {
        let p = Params::default();
        let ball = BallState::at_rest(1.0, 1.0, p.ball_radius);
        strike(
            &ball,
            &Cue {
                speed: 2.0,
                aim: 0.3,
                offset,
                elevation,
            },
            &p,
        )
    }

    #[test]
    fn centre_strike_is_a_stun_at_the_measured_transfer() {
        let s = hit([0.0, 0.0], 0.0).unwrap();
        assert_eq!(s.state.motion, Motion::Sliding);
        assert!(s.state.spin.norm() < 1e-12);
        assert!((s.speed_ratio - 1.45).abs() < 1e-12);
        assert!(s.squirt.abs() < 1e-12);
    }

    #[test]
    fn contact_at_seven_fifths_r_rolls_at_once() {
        let p = Params::default();
        // Horizontal cue: the contact's height above the centre is R/(R+r) of the axis height.
        let h = 0.4 * (p.ball_radius + p.cue_tip_radius);
        let s = hit([0.0, h], 0.0).unwrap();
        assert!((s.contact.z - 0.4 * p.ball_radius).abs() < 1e-15);
        assert_eq!(s.state.motion, Motion::Rolling);
    }

    #[test]
    fn squirt_is_two_and_a_half_degrees_at_twelve_mm_away_from_the_side_struck() {
        let p = Params::default();
        let axis = 0.012 * (p.ball_radius + p.cue_tip_radius) / p.ball_radius;
        let s = hit([axis, 0.0], 0.0).unwrap();
        // Right-hand side struck: the ball squirts left (positive angle).
        assert!(
            (s.squirt.to_degrees() - 2.5).abs() < 1e-9,
            "{}",
            s.squirt.to_degrees()
        );
        // Pushing the right side forward turns the ball anticlockwise seen from above
        // (positive w_z): r x F with r to the right and F forward points up.
        assert!(s.state.spin.z > 0.0);
        // Off-centre hits transfer less speed: along the cue, the ball's effective mass at the
        // contact is M / (1 + 5/2 (b/R)^2) (Alciatore, TP A.30).
        let b = 0.012 / p.ball_radius;
        let expect = (1.0 + p.cue_tip_restitution) / (p.ball_mass / p.cue_mass + 1.0 + 2.5 * b * b);
        assert!((s.speed_ratio * s.squirt.cos() - expect).abs() < 1e-12);
        assert!(s.speed_ratio < 1.45);
    }

    #[test]
    fn miscue_beyond_half_radius() {
        let e = hit([0.02, 0.0], 0.0).unwrap_err();
        assert_eq!(e.key, "offset");
        assert!(e.reason.contains("miscue"), "{}", e.reason);
        // Too low with a level cue: the tip would have to go through the cloth.
        assert!(hit([0.0, -0.02], 0.0).unwrap_err().reason.contains("cloth"));
        assert_eq!(hit([0.5, 0.0], 0.0).unwrap_err().key, "offset");
        assert_eq!(hit([0.0, 0.0], 1.6).unwrap_err().key, "elevation");
    }

    #[test]
    fn steep_cue_with_side_gives_a_curving_slide() {
        // Massé: spin about the heading makes the slip point sideways.
        let s = hit([0.008, 0.0], 1.0).unwrap();
        let slip = s.state.slip(Params::default().ball_radius);
        let v = s.state.vel;
        let cross = (v.x * slip.y - v.y * slip.x).abs() / (v.norm() * slip.norm());
        assert!(cross > 0.3, "slip not across the velocity: {cross}");
    }
}
