//! Validation of the snooker engine: the cross-check against rapier.
//!
//! A scene's [`snooker_engine::Setup`] is simulated by our event-driven engine and built as a
//! rapier world ([`rapier_world`], [`shapes`]) in which the table laws rapier lacks are applied
//! as external loads each step ([`table_laws`]); both runs are reduced to the same
//! [`digest::ShotDigest`] ([`rapier_run`] reads rapier's steps) and compared figure by figure
//! ([`compare`]) against tolerances derived from the known differences between the runs
//! ([`tolerance`]), over the whole shot or, with the frictional impact models, stretch by
//! stretch with rapier re-seeded from our state after each impact ([`stretch`]).
//! [`crosscheck`] runs one scene, [`scenes`] lists the scene set.

pub mod compare;
pub mod convergence;
pub mod crosscheck;
pub mod digest;
pub mod ensemble;
pub mod nose;
pub mod rapier_run;
pub mod rapier_world;
pub mod report;
pub mod scenes;
pub mod shapes;
pub mod stretch;
pub mod table_laws;
pub mod tolerance;
