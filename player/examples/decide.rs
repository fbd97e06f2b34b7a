//! Debugging: the player's decision for the frame of a play log's line
//! (`--example decide -- LOG.jsonl LINE [EFFORT]`).
use snooker_player::{Agent, Context, Player};
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&a[1]).unwrap();
    let k: usize = a[2].parse().unwrap();
    let effort: u64 = a.get(3).map_or(4000, |s| s.parse().unwrap());
    let line: serde_json::Value = serde_json::from_str(text.lines().nth(k - 1).unwrap()).unwrap();
    let f = snooker_rules::parse(line["frame"].as_str().unwrap(), "log").unwrap();
    // The choices made are the player's: undo the nomination.
    let frame = f.frame.with_nomination(None).unwrap_or(f.frame);
    let ctx = Context {
        noise: snooker_planner::Noise::STANDARD,
        seed: 1,
        stroke: k as u64,
        effort,
    };
    let d = Player.choose(&frame, &ctx).unwrap();
    println!("{:?}", d.plan);
}
