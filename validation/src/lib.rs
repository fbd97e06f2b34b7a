//! Validation of the snooker engine: the cross-check against rapier.
//!
//! A scene's [`snooker_engine::Setup`] is simulated by our event-driven engine and built as a
//! rapier world ([`rapier_world`], [`shapes`]) in which the table laws rapier lacks are applied
//! as external loads each step ([`table_laws`]); both runs are reduced to the same
//! [`record::Record`] ([`rapier_run`] reads rapier's steps) and compared figure by figure
//! ([`compare`]) against tolerances derived from the known differences between the runs
//! ([`tolerance`]). [`crosscheck`] runs one scene, [`scenes`] lists the scene set.

pub mod compare;
pub mod convergence;
pub mod crosscheck;
pub mod discrepancy;
pub mod ensemble;
pub mod nose;
pub mod rapier_run;
pub mod rapier_world;
pub mod record;
pub mod report;
pub mod scenes;
pub mod shapes;
pub mod table_laws;
pub mod tolerance;
