//! The `snooker` command-line tool's library: one module per command ([`cmd`]), around the
//! physics of `snooker-engine` and the formats of `snooker-scene`; Rerun recordings
//! ([`record`]), plots ([`plot`]), ball colours ([`palette`]) and output files ([`output`]).

pub mod cmd;
pub mod output;
pub mod palette;
pub mod plot;
pub mod record;
