//! Diagnostics: at each stroke of some visits, the closed-form best next pot (ball, pocket,
//! chance) beside what the player found and chose.
use snooker_planner::Noise;
use snooker_player::{PlayOptions, Player, Valuer, play};

fn main() {
    let seeds: u64 = std::env::args().nth(1).map_or(5, |s| s.parse().unwrap());
    for seed in 1..=seeds {
        let frame = snooker_player::layouts::open_table_in_hand(seed);
        let opts = PlayOptions {
            noise: Noise::STANDARD,
            seed,
            effort: 4000,
            ..PlayOptions::default()
        };
        let valuer = Valuer::new(&Noise::STANDARD, frame.params());
        let game = play(&frame, [&Player, &Player], &opts, |_| {}).unwrap();
        for s in &game.strokes {
            let f = s.frame.with_nomination(None).unwrap_or(s.frame.clone());
            let cue = f.cue_index().unwrap();
            let (v, best) = valuer.from(&f, f.balls()[cue].state.pos);
            let b = best
                .map(|(b, k)| format!("{} {}", f.balls()[b].id, f.table().pockets[k].name))
                .unwrap_or_default();
            let p = &s.decision.plan;
            let alts: Vec<String> = s
                .decision
                .alternatives
                .iter()
                .map(|a| format!("{} {} {:.2}", a.pot, a.pocket, a.pot_probability))
                .collect();
            println!(
                "seed {seed} stroke {}: closed form {b} value {v:.2} | chose {} {} p {:.2} ev {:.2} -> {} | {:?}",
                s.number, p.pot, p.pocket, p.pot_probability, p.value, s.verdict.points, alts
            );
        }
    }
}
