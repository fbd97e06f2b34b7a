//! An event-driven snooker physics engine.
//!
//! Between events every ball follows a closed-form law ([`motion`]: sliding, rolling,
//! spinning, airborne); the event detection (internal; its tolerances are [`TOUCH_TOL`],
//! [`VERIFY_TOL`] and [`SKIN`]) finds the next event exactly (ball-ball, cushion, jaw,
//! pocket, end of a law); [`impact`] resolves impacts with a model chosen per scene; [`sim`]
//! runs the loop and records a [`sim::Shot`] that can be evaluated at any time (positions,
//! velocities and, by [`sim::orientation`], each ball's orientation).
//!
//! Units are SI throughout; the frame is the table frame of [`table::snooker`].
//! The physics follows S. Mathavan's thesis (Loughborough University, 2009), cited by section.
//!
//! Embedding it takes a table, balls, an optional cue strike and one call:
//!
//! ```
//! use snooker_engine::cue::{self, Cue};
//! use snooker_engine::{
//!     Ball, BallKind, BallState, EventKind, Models, Params, Setup, SimOptions, SnookerDims,
//!     Table, simulate,
//! };
//!
//! let p = Params::default(); // the thesis's measured values
//! let r = p.ball_radius;
//! // Centres (x, y) in metres on the full-size table; balls rest on the cloth.
//! let cue_ball = BallState::at_rest(0.7, 0.889, r);
//! let red = BallState::at_rest(1.5, 0.889, r);
//! // A centre-ball strike at 2 m/s along +x, the cue level.
//! let aim = Cue { speed: 2.0, aim: 0.0, offset: [0.0, 0.0], elevation: 0.0 };
//! let struck = cue::strike(&cue_ball, &aim, &p).unwrap();
//! let setup = Setup {
//!     table: Table::snooker(&SnookerDims::default()),
//!     params: p,
//!     models: Models::default(), // the thesis's frictional impact models
//!     balls: vec![
//!         Ball { id: "cue".into(), kind: BallKind::Cue, state: struck.state },
//!         Ball { id: "red".into(), kind: BallKind::Red, state: red },
//!     ],
//! };
//! let shot = simulate(&setup, &SimOptions::default()).unwrap();
//! let hit = shot.events.iter().find(|e| e.kind == EventKind::BallBall).unwrap();
//! assert_eq!(hit.balls, [0, 1]);
//! assert!(hit.t > 0.0 && hit.t < 1.0);
//! // The exact trajectory can be read at any time; at the end every ball rests.
//! let red_later = shot.tracks[1].state_at(hit.t + 0.1, &shot.params);
//! assert!(red_later.pos.x > 1.5);
//! assert!(shot.final_states().iter().all(|s| !s.motion.is_moving()));
//! ```

pub mod audit;
pub mod ball;
pub mod cue;
pub(crate) mod detect;
pub mod impact;
pub mod motion;
pub mod params;
pub mod rng;
pub mod shown;
pub mod sim;
pub mod table;

pub use ball::{Ball, BallKind, BallState, Motion, Vec3};
pub use cue::{Cue, CueError, Strike};
pub use detect::{SKIN, TOUCH_TOL, VERIFY_TOL};
pub use impact::{BallBallModel, CushionModel, Models};
pub use params::Params;
pub use sim::{Ending, Event, EventKind, Setup, SetupError, Shot, SimError, SimOptions, simulate};
pub use table::{SnookerDims, Table, TableKind};
