//! Snooker by the rules: a [`Frame`] (the table, the physics, the balls at rest and the
//! [`FrameState`]: ball on, nomination, scores, turn, ball in hand, free ball), the referee's
//! [`Verdict`] on a stroke simulated by the engine ([`Frame::judge`]), and the frame that
//! follows ([`Frame::next`]), so that frame + strike -> frame + strike -> ... plays a whole
//! frame. The rules are the WPBSA Official Rules of Snooker as the contract in
//! `docs/formats.md` ("Frame", "Referee result") states them; `docs/rules.md` says which
//! rule each decision implements. No physics here: the engine simulates, this crate judges.
//!
//! ```
//! use snooker_engine::{simulate, Cue};
//! use snooker_rules::{Frame, Next, On};
//!
//! let frame = Frame::break_off();
//! // The break-off: the cue ball from the D, thin on the back red of the rack.
//! let strike = Cue { speed: 7.0, aim: 0.0465, offset: [0.0, 0.0], elevation: 0.0 };
//! let setup = frame.setup(&strike).unwrap();
//! let shot = simulate(&setup, frame.options()).unwrap();
//! let verdict = frame.judge(&shot).unwrap();
//! match frame.next(&verdict) {
//!     Next::Play(next) => assert!(next.state().on == On::Red || next.state().on == On::Colour),
//!     Next::Over { .. } => unreachable!("one stroke does not end a frame"),
//! }
//! ```

pub mod chain;
pub mod colour;
pub mod error;
pub mod file;
pub mod foul;
pub mod frame;
pub mod in_hand;
pub mod judge;
pub mod jump;
pub mod layout;
pub mod play;
pub mod report;
pub mod respot;
pub mod snookered;
pub mod state;
pub mod verdict;

pub use colour::Colour;
pub use error::{FrameError, JudgeError, Key, Problem};
pub use file::{FrameFile, from_value, load, parse, parse_json};
pub use foul::{Foul, FoulReason};
pub use frame::{Frame, Role};
pub use play::{PlayError, Stroke};
pub use report::RefereeReport;
pub use state::{FrameState, On, Player};
pub use verdict::{Next, Verdict};
