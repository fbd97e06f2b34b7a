//! Debugging: why a line of a log line's frame pots nothing (`-- LOG LINE BALL POCKET`).
use snooker_planner::Stroke;
fn main() {
    let a: Vec<String> = std::env::args().collect();
    let text = std::fs::read_to_string(&a[1]).unwrap();
    let k: usize = a[2].parse().unwrap();
    let line: serde_json::Value = serde_json::from_str(text.lines().nth(k - 1).unwrap()).unwrap();
    let f = snooker_rules::parse(line["frame"].as_str().unwrap(), "log").unwrap();
    let frame = f.frame.with_nomination(None).unwrap_or(f.frame);
    let targets = snooker_player::candidates::targets(&frame);
    for t in &targets {
        if frame.balls()[t.ball].id != a[3] || frame.table().pockets[t.pocket].name != a[4] {
            continue;
        }
        for l in t.problem.requested_lines() {
            if l.kind != snooker_planner::ShotKind::Direct {
                continue;
            }
            for &speed in &[0.5, 1.0, 1.9, 3.5] {
                for &h in &[-0.007, 0.0, 0.007] {
                    let s = Stroke {
                        speed,
                        side: 0.0,
                        height: h,
                        elevation: 0.035,
                        mouth: 0.0,
                    };
                    match t.problem.aimed_shot(&s, &l) {
                        Some((tr, shot)) => {
                            let v = t.frame.judge(&shot).unwrap();
                            println!(
                                "speed {speed} h {h}: fault {:?} kind {:?} verdict foul {:?} potted {:?} first {:?}",
                                tr.fault,
                                tr.kind,
                                v.foul.map(|f| f.reason),
                                v.potted,
                                v.first_hit
                            );
                        }
                        None => println!("speed {speed} h {h}: not aimed"),
                    }
                }
            }
        }
    }
}
