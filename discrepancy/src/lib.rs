//! The discrepancy workflow: given measured ball tracks (and post-event observables), find
//! where simulation and measurement disagree ([`locate`]), try the physical effects of the
//! [`catalogue`] the model lacks ([`fit`]), name the one the data demand, add it and repeat
//! ([`workflow`]); [`data_file`] reads the measured-data files (formats.md) and [`synth`] makes measured-like data with effects hidden in it, to prove the
//! workflow finds them. Thesis chapters 5 and 6 did this by hand: speed-time plots and
//! trial-and-error fits of friction and restitution.

pub mod catalogue;
pub mod crossval;
pub mod data;
pub mod data_file;
pub mod error;
pub mod fit;
pub mod locate;
pub mod report;
pub mod residuals;
pub mod synth;
pub mod workflow;

pub use catalogue::Effect;
pub use data::{Measurement, Model, Moment, Nuisance, Observable, Quantity, ShotData, TrackSample};
pub use error::DiscrepancyError;
pub use workflow::{EffectVerdict, Findings, Options, run};
