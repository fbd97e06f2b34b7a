//! Diagnostics: for each stroke of some visits, the geometry of the pot chosen (distance of the
//! cue ball to the contact, cut, distance to the pocket, the cue ball's gap to the nearest
//! cushion), its closed-form chance and the share of its noise samples potted.
use snooker_engine::Vec3;
use snooker_planner::Noise;
use snooker_player::chance::{self, Direct};
use snooker_player::{PlayOptions, Player, play};

fn main() {
    let seeds: u64 = std::env::args().nth(1).map_or(5, |s| s.parse().unwrap());
    let scale: f64 = std::env::args().nth(2).map_or(1.0, |s| s.parse().unwrap());
    for seed in 1..=seeds {
        let frame = snooker_player::layouts::open_table_in_hand(seed);
        let noise = Noise::STANDARD.scaled(scale);
        let opts = PlayOptions {
            noise,
            seed,
            effort: 4000,
            ..PlayOptions::default()
        };
        let game = play(&frame, [&Player, &Player], &opts, |_| {}).unwrap();
        for s in &game.strokes {
            let p = &s.decision.plan;
            if p.pot.is_empty() {
                continue;
            }
            let f = &s.frame;
            let r = f.params().ball_radius;
            let cue = f.balls()[f.cue_index().unwrap()].state.pos;
            let b = f.balls().iter().find(|b| b.id == p.pot).unwrap().state.pos;
            let pocket = f
                .table()
                .pockets
                .iter()
                .find(|k| k.name == p.pocket)
                .unwrap();
            let flat = |v: Vec3| Vec3::new(v.x, v.y, 0.0);
            let sd = chance::direction_sd(&Noise::STANDARD, f.params());
            let d = Direct::new(flat(cue), flat(b), pocket, r);
            let (l, w) = (f.table().length, f.table().width);
            let cushion = [cue.x, l - cue.x, cue.y, w - cue.y]
                .into_iter()
                .fold(f64::INFINITY, f64::min)
                - r;
            let potted = s.verdict.legal() && s.verdict.potted.contains(&p.pot);
            match d {
                Some(d) => println!(
                    "{seed:>2} {:>2} {:<6} d {:.2} cut {:>4.1} D {:.2} cushion {:.3} closed {:.2} mc {:.2} speed {:.2} h {:+.4} side {:+.4} {}",
                    s.number,
                    p.kind.name(),
                    d.to_contact,
                    d.cut.to_degrees(),
                    d.to_pocket,
                    cushion,
                    d.chance(pocket, sd, r),
                    p.pot_probability,
                    s.decision.strike.speed,
                    s.decision.strike.offset[1],
                    s.decision.strike.offset[0],
                    if potted { "pot" } else { "MISS" }
                ),
                None => println!(
                    "{seed:>2} {:>2} {:<6} (no direct geometry) mc {:.2} {}",
                    s.number,
                    p.kind.name(),
                    p.pot_probability,
                    if potted { "pot" } else { "MISS" }
                ),
            }
        }
    }
}
