//! The command line's small languages, shared by its commands: `--param NAME=VALUE`. The
//! libraries take typed values; only the command line reads these strings and names its flags
//! in messages.

use snooker_engine::Params;
use snooker_scene::OverrideError;

/// `NAME=VALUE` overrides as (name, value) pairs; a malformed one is a message naming it.
pub fn param_pairs(given: &[String]) -> Result<Vec<(String, f64)>, String> {
    given
        .iter()
        .map(|o| {
            let (name, value) = o
                .split_once('=')
                .ok_or_else(|| format!("--param {o}: expected NAME=VALUE"))?;
            let v: f64 = value
                .trim()
                .parse()
                .map_err(|_| format!("--param {o}: {value} is not a number"))?;
            Ok((name.trim().to_string(), v))
        })
        .collect()
}

/// An override error as the command says it, naming the `--param` given.
pub fn param_error(given: &[String], e: &OverrideError) -> String {
    let shown = given
        .iter()
        .find(|o| o.split_once('=').map(|(n, _)| n.trim()) == Some(e.name()))
        .map_or(e.name(), String::as_str);
    match e {
        OverrideError::Unknown { .. } => format!("--param {shown}: {e}"),
        OverrideError::Invalid(_) => format!("--param {e}"),
    }
}

/// `base` with the `--param NAME=VALUE` overrides applied and checked.
pub fn params(base: Params, given: &[String]) -> Result<Params, String> {
    snooker_scene::override_params(base, &param_pairs(given)?).map_err(|e| param_error(given, &e))
}
