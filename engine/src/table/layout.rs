//! Standard ball layouts.

use super::snooker::SnookerDims;
use crate::ball::{Ball, BallKind, BallState, Vec3};

/// Gap left between the pink and the apex red of the triangle, m. The rules ask for the apex
/// red "as near to the pink as possible without touching it"; 1 mm is an assumption.
pub const PINK_GAP: f64 = 0.001;

/// Names of the standard layouts.
pub const LAYOUTS: [&str; 1] = ["break-off"];

/// The break-off layout: 15 touching reds in a triangle behind the pink (apex towards the
/// pink), the colours on their spots and the cue ball in the D between the brown and yellow spots.
pub fn break_off(dims: &SnookerDims, radius: f64) -> Vec<Ball> {
    let mut balls = Vec::new();
    let mut add = |id: String, pos: Vec3| {
        balls.push(Ball {
            kind: BallKind::from_id(&id),
            id,
            state: BallState::at_rest(pos.x, pos.y, radius),
        })
    };
    let brown = dims.spot("brown").expect("brown spot");
    add(
        "cue".into(),
        brown - Vec3::new(0.0, 0.5 * dims.d_radius, 0.0),
    );
    for spot in dims.spots() {
        add(spot.name.into(), spot.pos);
    }
    let pink = dims.spot("pink").expect("pink spot");
    let apex = pink.x + 2.0 * radius + PINK_GAP;
    let row_step = 3f64.sqrt() * radius;
    let mut n = 0;
    for row in 0..5 {
        for j in 0..=row {
            n += 1;
            let x = apex + row as f64 * row_step;
            let y = pink.y + (j as f64 - row as f64 / 2.0) * 2.0 * radius;
            add(format!("red{n}"), Vec3::new(x, y, 0.0));
        }
    }
    balls
}

/// A layout by name, or `None` if there is no such layout.
pub fn by_name(name: &str, dims: &SnookerDims, radius: f64) -> Option<Vec<Ball>> {
    match name {
        "break-off" => Some(break_off(dims, radius)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reds_touch_and_nothing_overlaps() {
        let d = SnookerDims::default();
        let r = 0.0262;
        let balls = break_off(&d, r);
        assert_eq!(balls.len(), 22);
        let mut touching = 0;
        for (i, a) in balls.iter().enumerate() {
            for b in &balls[i + 1..] {
                let gap = (a.state.pos - b.state.pos).norm() - 2.0 * r;
                assert!(gap > -1e-12, "{} {} overlap", a.id, b.id);
                if gap.abs() < 1e-12 {
                    touching += 1;
                }
            }
        }
        // A triangle of 15 has 30 touching pairs.
        assert_eq!(touching, 30);
    }
}
