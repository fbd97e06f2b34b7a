//! Debugging: the closed-form value of each log line's frame (`Valuer::position`, the
//! nomination undone) beside the value the player's noise samples found for the stroke played
//! from it (`-- LOG.jsonl`).
use snooker_player::Valuer;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&a[1]).unwrap();
    for line in text.lines() {
        let line: serde_json::Value = serde_json::from_str(line).unwrap();
        let f = snooker_rules::parse(line["frame"].as_str().unwrap(), "log").unwrap();
        let frame = f.frame.with_nomination(None).unwrap_or(f.frame);
        let valuer = Valuer::new(&snooker_planner::Noise::STANDARD, frame.params());
        let plan = &line["plan"];
        println!(
            "{} closed-form {:+.2} sampled {:+.2} p {:.2} {} {}",
            line["stroke"],
            valuer.position(&frame),
            plan["value"].as_f64().unwrap(),
            plan["pot_probability"].as_f64().unwrap(),
            plan["kind"],
            plan["pot"]
        );
    }
}
