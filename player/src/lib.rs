//! A snooker player on the engine: from any frame it chooses and plays stroke after stroke
//! under execution noise, and builds breaks: the thesis's "strategy-planning element" (§2.1,
//! §7.3.1), which its robot left to a human.
//!
//! [`Player`] plans candidate pots of every kind with the planner ([`snooker_planner`]:
//! direct, doubles, plants, kisses), the planner's objective being the value of the position
//! each leaves ([`value`]: the next ball on's chance of a pot, in closed form, [`chance`]);
//! the best are played many times under sampled noise and judged by the rules
//! ([`snooker_rules`]), and the stroke of the highest expected value in points is chosen
//! ([`outcome`]); a safety when no pot is worth its risk; the cue ball in hand placed where the
//! pots are best. [`Greedy`] is the baseline: the likeliest pot, no position, no safety.
//! [`play`] plays a visit or a frame; [`StrokeRecord::log_line`] writes the play log
//! (formats.md, "Play log"). A [`Watch`] in the options counts the shots simulated and stops
//! the play when its flag is raised (the shot lab's progress bar and cancel button).
//!
//! ```no_run
//! use snooker_player::{Player, PlayOptions, play};
//! use snooker_rules::Frame;
//! let frame = Frame::open_table(15, 7);
//! let game = play(&frame, [&Player, &Player], &PlayOptions::default(), |_| {}).unwrap();
//! println!("break of {}", game.points(0));
//! ```

pub mod agent;
pub mod candidates;
pub mod chance;
pub mod decision;
pub mod game;
pub mod greedy;
pub mod layouts;
pub mod log;
pub mod outcome;
mod placement;
pub mod player;
mod safety;
mod sampling;
mod search;
pub mod spread;
pub mod value;
pub mod watch;

pub use agent::{Agent, ChooseError, Context};
pub use decision::{Considered, Decision, PlanKind};
pub use game::{End, Game, PlayError, PlayOptions, StrokeRecord, Until, executed, play};
pub use greedy::Greedy;
pub use player::Player;
pub use value::Valuer;
pub use watch::Watch;
