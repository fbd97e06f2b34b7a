//! The impact problem and its answer, as data: the two bodies and their contact, their
//! velocities before and after, and samples of the impact's progress.

use crate::ball::{INV_INERTIA_FACTOR, Vec3};

/// One body of an impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImpactBody {
    /// M / mass (1 for a ball, 0 for a fixed cushion).
    pub inv_mass: f64,
    /// M R^2 / moment of inertia (5/2 for a solid ball, 0 for a fixed cushion).
    pub inv_inertia: f64,
    /// True when the body rests on the cloth at the start (so the cloth can hold it).
    pub on_cloth: bool,
}

impl ImpactBody {
    /// A solid ball of the reference mass and radius.
    pub fn ball(on_cloth: bool) -> ImpactBody {
        ImpactBody {
            inv_mass: 1.0,
            inv_inertia: INV_INERTIA_FACTOR,
            on_cloth,
        }
    }

    /// An immovable body (the cushion).
    pub fn fixed() -> ImpactBody {
        ImpactBody {
            inv_mass: 0.0,
            inv_inertia: 0.0,
            on_cloth: false,
        }
    }

    /// Whether no impulse moves the body (zero inverse mass and inertia).
    pub fn is_fixed(&self) -> bool {
        self.inv_mass == 0.0 && self.inv_inertia == 0.0
    }
}

/// The geometry and coefficients of an impact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impact {
    /// The two bodies.
    pub bodies: [ImpactBody; 2],
    /// Unit normal at the primary contact, from body 0 towards body 1.
    pub normal: Vec3,
    /// The primary contact point relative to each body's centre, in units of R.
    pub arm: [Vec3; 2],
    /// Friction at the primary contact.
    pub mu: f64,
    /// Friction at the cloth during the impact.
    pub mu_cloth: f64,
    /// Energetic coefficient of restitution.
    pub e: f64,
    /// A compliant cushion's backing (None: a rigid contact, restitution e throughout).
    pub backing: Option<Backing>,
}

/// The stiff, damped backing behind a cushion rubber of finite travel (the compliant cushion,
/// [`crate::impact::cushion::compliant`]): the rubber takes the compression's work up to
/// `bottom_energy` and gives back e^2 of it; the work beyond goes into the backing, which
/// gives back (1 - `damping` v)^2 of it, v being the speed at which a ball of the reference
/// mass carries that work (Hunt and Crossley 1975: restitution 1 - alpha v for a contact
/// force k d^n (1 + 3/2 alpha d')).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Backing {
    /// Work of the normal impulse at which the rubber's travel is used up, J.
    pub bottom_energy: f64,
    /// The backing's Hunt-Crossley damping alpha, s/m.
    pub damping: f64,
}

/// Velocities of the two bodies (m/s, rad/s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics {
    /// Centre velocities.
    pub vel: [Vec3; 2],
    /// Angular velocities.
    pub spin: [Vec3; 2],
}

/// What the impact did.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resolution {
    /// Velocities just after the impact.
    pub after: Kinematics,
    /// Total normal impulse, N s.
    pub impulse: f64,
    /// Normal impulse at the end of compression, N s.
    pub compression_impulse: f64,
    /// Accepted integration steps.
    pub steps: usize,
    /// Phases between switches.
    pub phases: usize,
}

/// One sample of an impact's progress, for plots of slip against impulse (thesis fig. 6.14).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Normal impulse so far, N s.
    pub impulse: f64,
    /// Slip velocity at the primary contact (body 0 relative to body 1), m/s.
    pub slip: Vec3,
    /// Cloth slip of each body, m/s (zero when it does not touch the cloth).
    pub cloth_slip: [Vec3; 2],
    /// Whether the cloth presses on each body (only then does its cloth slip meet friction).
    pub pressed: [bool; 2],
    /// Normal relative velocity (positive approaching), m/s.
    pub normal_velocity: f64,
}
