//! A small load run on loopback (the figures come from the load example, not from here): many
//! concurrent simulations and plans all answered without error, and memory flat over rounds
//! (no growth per request beyond what the first rounds settle on). No timing is asserted.

mod common;
use common::load;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn concurrent_requests_all_succeed_and_memory_stays_flat() {
    let r = load::run(24, 2, 16, 6).await;
    assert!(r.errors.is_empty(), "{:?}", r.errors);
    assert_eq!(r.simulations, 24 * 6);
    assert_eq!(r.plans, 2 * 6);
    // After two rounds to warm up (allocator pools, thread stacks, the kept jobs filling),
    // the resident memory grows by less than 16 MB over four more rounds of 26 requests.
    let warm = r.rss_kb[1];
    let last = *r.rss_kb.last().unwrap();
    assert!(
        last < warm + 16 * 1024,
        "memory grew from {warm} kB to {last} kB: {:?}",
        r.rss_kb
    );
}
