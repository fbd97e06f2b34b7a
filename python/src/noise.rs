//! The `noise` argument of `plan`, `play` and `choose`: one reading for all three, so that a
//! spelling one refuses the others refuse too and their messages name the key alike.

use crate::argument;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use snooker_planner::{Noise, NoiseComponent, PlanError};
use std::collections::BTreeMap;

/// `base` with the standard deviations `given` by name (`aim`, `elevation`, `speed`, `side`,
/// `height`; `offset` sets side and height), checked. The old spelling, `speed` as a fraction
/// of the cue speed beside one `offset`, is refused rather than read with today's meaning.
pub fn from_dict(base: Noise, given: BTreeMap<String, f64>) -> PyResult<Noise> {
    if given.contains_key("offset") && given.contains_key("speed") {
        return Err(PyValueError::new_err(
            "noise: the old spelling (speed as a fraction of the cue speed, one offset) is no \
             longer read: speed is now in m/s (the old speed=F at cue speed V is F*V) and \
             offset is side and height",
        ));
    }
    let mut n = base;
    for (name, sd) in given {
        if name == "offset" {
            n.side = sd;
            n.height = sd;
            continue;
        }
        let c = NoiseComponent::from_name(&name).ok_or_else(|| {
            PyValueError::new_err(format!(
                "noise['{name}']: unknown noise (aim, elevation, speed, side, height; or offset)"
            ))
        })?;
        n.set(c, sd);
    }
    n.check().map_err(|e| match e {
        PlanError::BadInput { field, reason } => {
            PyValueError::new_err(format!("{}: {reason}", argument(field)))
        }
        other => PyValueError::new_err(format!("noise: {other}")),
    })?;
    Ok(n)
}
