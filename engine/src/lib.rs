//! An event-driven snooker physics engine.
//!
//! Between events every ball follows a closed-form law ([`motion`]: sliding, rolling,
//! spinning, airborne); [`detect`] finds the next event exactly (ball-ball, cushion, jaw,
//! pocket, end of a law); [`impact`] resolves impacts with a model chosen per scene; [`sim`]
//! runs the loop and records a [`sim::Shot`] that can be evaluated at any time.
//!
//! Units are SI throughout; the frame is the table frame of [`table::snooker`].
//! The physics follows S. Mathavan's thesis (Loughborough University, 2009), cited by section.

pub mod ball;
pub mod cue;
pub mod detect;
pub mod impact;
pub mod motion;
pub mod params;
pub mod sim;
pub mod table;

pub use ball::{Ball, BallKind, BallState, Motion, Vec3};
pub use cue::{Cue, CueError, Strike};
pub use impact::{BallBallModel, CushionModel, Models};
pub use params::Params;
pub use sim::{Ending, Event, EventKind, Setup, SetupError, Shot, SimError, SimOptions, simulate};
pub use table::{SnookerDims, Table, TableKind};
