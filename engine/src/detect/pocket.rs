//! Pocket capture: the ball drops once its centre enters the fall circle (plan).

use super::roots::first_entry;
use crate::motion::Path;
use crate::table::Pocket;

/// First time in [0, window] at which `path`'s centre enters the fall of `pocket`.
pub fn capture_time(path: &Path, pocket: &Pocket, window: f64) -> Option<f64> {
    let mut rel = path.plan();
    rel.c -= pocket.centre;
    first_entry(&rel, pocket.radius, window)
}
