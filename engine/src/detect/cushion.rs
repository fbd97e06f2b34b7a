//! Ball-cushion contact. The nose touches the ball at height h (7R/5), so a ball touches a
//! straight nose when its centre is R cos(theta) from the nose line in plan (thesis §6.2),
//! and a jaw arc of radius r_j when its centre is r_j + R cos(theta) from the arc's centre.
//! Airborne balls are tested in plan with the same distance (their hop is a few mm).

use super::TOUCH_TOL;
use super::roots::{first_entry, first_line_contact};
use crate::motion::Path;
use crate::table::{Cushion, Jaw};

/// First time in [0, window] at which `path` touches the straight `cushion` within its
/// length, approaching it; `contact` is R cos(theta).
pub fn nose_time(path: &Path, cushion: &Cushion, contact: f64, window: f64) -> Option<f64> {
    let (t, at) = first_line_contact(&path.plan(), cushion.start, cushion.normal, contact, window)?;
    let along = (at - cushion.start).dot(&cushion.direction());
    (along >= -TOUCH_TOL && along <= cushion.length() + TOUCH_TOL).then_some(t)
}

/// First time in [0, window] at which `path` touches the `jaw` arc, approaching it.
pub fn jaw_time(path: &Path, jaw: &Jaw, contact: f64, window: f64) -> Option<f64> {
    let mut rel = path.plan();
    rel.c -= jaw.centre;
    first_entry(&rel, jaw.radius + contact, window)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Vec3;

    #[test]
    fn misses_beyond_the_end_of_the_nose() {
        let cushion = Cushion {
            name: "c".into(),
            start: Vec3::new(0.0, 0.0, 0.0),
            end: Vec3::new(1.0, 0.0, 0.0),
            normal: Vec3::y(),
        };
        let toward = |x: f64| Path {
            c: Vec3::new(x, 0.5, 0.0),
            b: Vec3::new(0.0, -1.0, 0.0),
            a: Vec3::zeros(),
        };
        assert!(nose_time(&toward(0.5), &cushion, 0.024, 1.0).is_some());
        assert!(nose_time(&toward(1.1), &cushion, 0.024, 1.0).is_none());
    }
}
