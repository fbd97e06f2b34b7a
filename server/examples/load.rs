//! The shot lab under load, on loopback: rounds of concurrent simulations and plans against a
//! server in this process; prints the latencies (median, 95th percentile, slowest) and the
//! resident memory after each round. The figures in docs/shotlab.md come from
//!
//!   cargo run --profile ci -p snooker-server --example load -- 64 4 64 10
//!
//! (arguments: concurrent simulations per round, concurrent plans per round, noise samples
//! per plan, rounds). Exits with 1 on any error or any request slower than the bound stated
//! in docs/shotlab.md (simulations 5 s, plans 60 s, on 2 cores).

#[path = "../tests/common/load.rs"]
mod load;

/// kB figures as MB, listed.
fn mb(kb: &[u64]) -> String {
    let list: Vec<String> = kb
        .iter()
        .map(|k| format!("{:.1}", *k as f64 / 1024.0))
        .collect();
    list.join(", ")
}

fn arg(n: usize, default: usize) -> usize {
    std::env::args()
        .nth(n)
        .and_then(|a| a.parse().ok())
        .unwrap_or(default)
}

#[tokio::main(flavor = "multi_thread")]
async fn main() -> std::process::ExitCode {
    let (clients, plans, samples, rounds) = (arg(1, 64), arg(2, 4), arg(3, 64), arg(4, 10));
    println!(
        "{rounds} rounds of {clients} simulations and {plans} plans ({samples} samples) at once"
    );
    // SHOTLAB_TRIM=1: the allocator's free memory handed back after each round.
    let trim = std::env::var("SHOTLAB_TRIM").is_ok_and(|v| v == "1");
    let mut r = load::run(
        snooker_server::Limits::default(),
        clients,
        plans,
        samples,
        rounds,
        trim,
    )
    .await;
    let (sim_max, plan_max) = (
        load::quantile(&mut r.simulate_times, 1.0),
        load::quantile(&mut r.plan_times, 1.0),
    );
    println!(
        "simulations: {} answered; median {:.3} s, 95th percentile {:.3} s, slowest {:.3} s",
        r.simulations,
        load::quantile(&mut r.simulate_times, 0.5),
        load::quantile(&mut r.simulate_times, 0.95),
        sim_max
    );
    println!(
        "plans: {} done; median {:.2} s, 95th percentile {:.2} s, slowest {:.2} s",
        r.plans,
        load::quantile(&mut r.plan_times, 0.5),
        load::quantile(&mut r.plan_times, 0.95),
        plan_max
    );
    println!("resident memory after each round, MB: {}", mb(&r.rss_kb));
    println!("heap live after each round, MB: {}", mb(&r.live_kb));
    println!("wall time {:.1} s; errors: {}", r.wall, r.errors.len());
    for e in r.errors.iter().take(10) {
        println!("  {e}");
    }
    let slow = sim_max > 5.0 || plan_max > 60.0;
    if slow {
        println!("a request was slower than the bound (simulations 5 s, plans 60 s)");
    }
    if r.errors.is_empty() && !slow {
        std::process::ExitCode::SUCCESS
    } else {
        std::process::ExitCode::FAILURE
    }
}
