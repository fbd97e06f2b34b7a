//! Diagnostics of position play (issue 23): one JSON line per stroke of open-table visits,
//! with what the player expected of each pot (the sampled chance, the closed-form chance of
//! that pot and of the best pot from where the cue ball lies), whether it potted, the pot's
//! geometry (cut, distances), and the position it came from: where the previous stroke meant
//! to leave the cue ball, how far from there it stopped, the best pot's closed-form chance
//! from the planned end, and whether the cue ball ran into another ball on the way.
//!
//! `cargo run --profile ci -p snooker-player --example attempts -- FROM TO [EFFORT] [NOISE]`
//! (layouts FROM..=TO, seed k on layout k); `scripts/position_diagnosis.py` sums the lines up.
use snooker_engine::{EventKind, Shot, Vec3};
use snooker_planner::Noise;
use snooker_player::chance::Direct;
use snooker_player::spread::Spread;
use snooker_player::{PlanKind, PlayOptions, Player, StrokeRecord, Valuer, play};
use snooker_rules::Frame;

/// The cue ball's contacts after its first: (balls, cushions), and its path's length from its
/// first contact, m.
fn cue_way(shot: &Shot, cue: usize) -> (usize, usize, f64) {
    let mut balls = 0;
    let mut cushions = 0;
    let mut first = None;
    for e in &shot.events {
        if !e.balls.contains(&cue) {
            continue;
        }
        match e.kind {
            EventKind::BallBall => {
                if first.is_none() {
                    first = Some(e.t);
                } else {
                    balls += 1;
                }
            }
            EventKind::BallCushion if first.is_some() => cushions += 1,
            _ => {}
        }
    }
    let Some(t0) = first else {
        return (balls, cushions, 0.0);
    };
    let track = &shot.tracks[cue];
    let steps = 64;
    let mut len = 0.0;
    let mut prev = track.state_at(t0, &shot.params).pos;
    for k in 1..=steps {
        let t = t0 + (shot.duration - t0) * k as f64 / steps as f64;
        let q = track.state_at(t, &shot.params).pos;
        len += (q - prev).xy().norm();
        prev = q;
    }
    (balls, cushions, len)
}

/// The closed-form chance of potting ball `id` in pocket `pocket` from `cue` in `frame`, with
/// its cut (degrees) and distances; None when not a direct pot the closed form knows.
fn direct(frame: &Frame, valuer: &Valuer, cue: Vec3, id: &str, pocket: &str) -> Option<[f64; 4]> {
    let r = frame.params().ball_radius;
    let b = frame.balls().iter().find(|b| b.id == id)?;
    let p = frame.table().pockets.iter().find(|p| p.name == pocket)?;
    let ball = Vec3::new(b.state.pos.x, b.state.pos.y, 0.0);
    let d = Direct::new(Vec3::new(cue.x, cue.y, 0.0), ball, p, r)?;
    Some([
        d.chance(p, valuer.sd, r),
        d.cut.to_degrees(),
        d.to_contact,
        d.to_pocket,
    ])
}

/// The best direct pot's closed-form chance from `cue` in `frame` (any ball on).
fn best_chance(frame: &Frame, valuer: &Valuer, cue: Vec3) -> (f64, String) {
    let f = frame
        .with_nomination(None)
        .unwrap_or_else(|_| frame.clone());
    let (_, best) = valuer.from(&f, cue);
    match best {
        Some((b, k)) => {
            let id = f.balls()[b].id.clone();
            let pocket = f.table().pockets[k].name.clone();
            let c = direct(&f, valuer, cue, &id, &pocket).map_or(0.0, |d| d[0]);
            (c, format!("{id} {pocket}"))
        }
        None => (0.0, String::new()),
    }
}

fn line(seed: u64, s: &StrokeRecord, prev: Option<&StrokeRecord>, valuer: &Valuer) -> String {
    let f = &s.frame;
    let cue = f.cue_index().map(|i| f.balls()[i].state.pos).unwrap();
    let p = &s.decision.plan;
    let potted = s.verdict.legal() && s.verdict.potted.contains(&p.pot);
    let geometry = if p.kind == PlanKind::Direct {
        direct(f, valuer, cue, &p.pot, &p.pocket)
    } else {
        None
    };
    let (best_c, best) = best_chance(f, valuer, cue);
    let robust_here = valuer.robust(
        &f.with_nomination(None).unwrap_or_else(|_| f.clone()),
        // No spread: the value at the point itself.
        &Spread::along_path(1.0, 0.0, 0.0, Vec3::zeros()),
    );
    let max_alt = s
        .decision
        .alternatives
        .iter()
        .filter(|a| a.kind != PlanKind::Safety)
        .map(|a| a.pot_probability)
        .fold(0.0, f64::max);
    // The position it came from: the previous stroke's, if it potted and the same player is on.
    let from = prev
        .filter(|q| q.player == s.player && q.verdict.legal() && !q.verdict.potted.is_empty())
        .map(|q| {
            let planned = Vec3::new(q.decision.plan.cue_to[0], q.decision.plan.cue_to[1], 0.0);
            let err = (Vec3::new(cue.x, cue.y, 0.0) - planned).xy().norm();
            let (planned_c, planned_best) = best_chance(f, valuer, planned);
            let qc = q.frame.cue_index().unwrap();
            let (balls, cushions, path) = cue_way(&q.shot, qc);
            // The same stroke played as meant: did its cue ball run into a ball too?
            let meant = q.frame.play(&q.decision.strike).ok();
            let (meant_balls, meant_cushions, meant_path) =
                meant.map_or((0, 0, 0.0), |m| cue_way(&m.shot, qc));
            serde_json::json!({
                "kind": q.decision.plan.kind.name(),
                "end_error": err,
                "planned_best_chance": planned_c,
                "planned_best": planned_best,
                "same_pot_as_planned": planned_best == format!("{} {}", p.pot, p.pocket),
                "cue_balls_hit_after_first": balls,
                "cue_cushions": cushions,
                "cue_path": path,
                "meant_balls_hit_after_first": meant_balls,
                "meant_cushions": meant_cushions,
                "meant_path": meant_path,
                "speed": q.decision.strike.speed,
                "value": q.decision.plan.value,
            })
        });
    serde_json::json!({
        "seed": seed,
        "stroke": s.number,
        "kind": p.kind.name(),
        "on": f.state().on.name(),
        "pot": p.pot,
        "pocket": p.pocket,
        "sampled": p.pot_probability,
        "samples": p.samples,
        "value": p.value,
        "potted": potted,
        "legal": s.verdict.legal(),
        "points": s.verdict.points,
        "closed_chance": geometry.map(|g| g[0]),
        "cut": geometry.map(|g| g[1]),
        "to_contact": geometry.map(|g| g[2]),
        "to_pocket": geometry.map(|g| g[3]),
        "best_chance_here": best_c,
        "best_here": best,
        "robust_here": robust_here,
        "max_alt_sampled": max_alt,
        "in_hand": s.decision.placement.is_some(),
        "from": from,
        "shots": s.decision.shots,
    })
    .to_string()
}

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let from: u64 = a.get(1).map_or(1, |s| s.parse().unwrap());
    let to: u64 = a.get(2).map_or(20, |s| s.parse().unwrap());
    let effort: u64 = a.get(3).map_or(4000, |s| s.parse().unwrap());
    let scale: f64 = a.get(4).map_or(1.0, |s| s.parse().unwrap());
    let noise = Noise::STANDARD.scaled(scale);
    for seed in from..=to {
        let frame = snooker_player::layouts::open_table_in_hand(seed);
        let valuer = Valuer::new(&noise, frame.params());
        let opts = PlayOptions {
            noise,
            seed,
            effort,
            ..PlayOptions::default()
        };
        let game = play(&frame, [&Player, &Player], &opts, |_| {}).unwrap();
        for (i, s) in game.strokes.iter().enumerate() {
            let prev = i.checked_sub(1).map(|j| &game.strokes[j]);
            println!("{}", line(seed, s, prev, &valuer));
        }
    }
}
