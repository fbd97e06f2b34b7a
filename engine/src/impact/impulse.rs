//! Frictional 3D impact dynamics in impulse space, shared by the two Mathavan models
//! (thesis §6.1, §6.2; Mathavan, Jackson and Parkin 2010; Stronge, *Impact Mechanics* 2000).
//!
//! Two rigid bodies meet at a primary contact (ball-ball, or ball-cushion with the cushion a
//! body of zero inverse mass). The normal impulse P at that contact grows monotonically during
//! the impact and is the independent variable. Forces per unit dP:
//! - at the primary contact: the normal impulse along n (from body 0 to body 1), and Coulomb
//!   friction mu against the slip of body 0's contact point relative to body 1's;
//! - at the cloth under each ball that rests on it: a reaction N that keeps the ball's vertical
//!   velocity at zero while the other forces push the ball down (a unilateral constraint: the
//!   ball whose contact is pushed down presses the cloth, the other lifts off, thesis §6.1.2;
//!   for the cushion this gives dP_C = (sin theta + mu_w sin Phi cos theta) dP_I, eq. 6.28),
//!   and friction mu_s N against the cloth slip.
//!
//! Slip directions are free to change during the impact. Friction is Coulomb's law: against
//! the slip while there is one; at zero slip the contact holds if the friction needed is at
//! most mu N, and otherwise creeps out of zero in the one direction its friction leaves
//! growing. The thesis states "no stick" (§6.1.2.1, §6.2.2.1: friction stops when a slip
//! reaches zero); taken literally that is ill-posed whenever other forces keep driving the
//! slip (the friction then flips every instant), and a fixed-step scheme that re-evaluates the
//! slip direction every step (the thesis's own) converges to this law. Where nothing drives a
//! stopped slip, as in most snooker impacts, the two agree.
//!
//! Restitution is energetic (Stronge): compression ends when the normal relative velocity
//! vanishes; the impact ends when the work of the normal impulse, W(P) = integral of v_n dP,
//! reaches (1 - e^2) W(P_c) (thesis eqs. 6.12, 6.38). A compliant cushion gives back a share
//! of W(P_c) that depends on its size (`restitution`): with rate-independent friction the
//! normal compliance changes nothing else in impulse space (Stronge 2000, §2.3 and ch. 5).
//!
//! The equations are integrated adaptively (an internal Dormand-Prince 5(4) integrator,
//! `dopri.rs`) in units of the approach speed V, the ball mass M and radius R; every switch
//! (end of compression, a slip stopping, turning or becoming established, a ball pressing or
//! lifting, the end of the impact) is an event located on the integrator's continuous
//! extension.
//!
//! Where each part lives:
//! - `problem`: the bodies, their contact and velocities, the outcome (data only);
//! - `pair`: the scaled state, generic over the body pair (both free, or a fixed cushion);
//! - `mode`: each contact's friction law in a phase, and the mode at a state;
//! - `laws`: the forces per unit impulse and the state's rates, written once;
//! - `coulomb`: Coulomb's law at zero slip (hold, creep);
//! - `events`: the named switches and their event functions;
//! - `measure`: the slip-aware step error;
//! - `phase`: one phase's laws and its integration; `establish`: Heun's step for a slip
//!   growing out of zero;
//! - `restitution`: the work at which restitution ends (rigid, or a compliant backing);
//! - `solve`: the phases from approach to separation; `euler`: the thesis's own scheme.

mod coulomb;
mod error;
mod establish;
mod euler;
mod events;
mod laws;
mod measure;
mod mode;
mod pair;
mod phase;
mod problem;
mod restitution;
mod solve;

pub use error::ImpactError;
pub use problem::{Backing, Impact, ImpactBody, Kinematics, Resolution, Sample};
pub use solve::TOLERANCE;

#[cfg(test)]
mod tests;
