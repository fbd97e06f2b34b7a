//! A small load run on loopback (the figures come from the load example, not from here): many
//! concurrent simulations and plans all answered without error, and memory flat over rounds
//! (no growth per request beyond what the first rounds settle on). No timing is asserted.

mod common;
use common::load;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn concurrent_requests_all_succeed_and_memory_stays_flat() {
    // Few finished jobs kept, so that their results stop adding up within the run.
    let limits = snooker_server::Limits {
        kept_jobs: 4,
        ..snooker_server::Limits::default()
    };
    let r = load::run(limits, 24, 2, 16, 8, false).await;
    assert!(r.errors.is_empty(), "{:?}", r.errors);
    assert_eq!(r.simulations, 24 * 8);
    assert_eq!(r.plans, 2 * 8);
    // After three rounds to warm up (allocator pools, thread stacks, the kept jobs filling),
    // the heap the program holds (live bytes, counted by the test's allocator) grows by less
    // than 2 MB over five more rounds of 26 requests: a leak of every answer, tens to hundreds
    // of kB each over 130 requests, would not fit. The resident size, which also counts what
    // the allocator keeps from the system (docs/shotlab.md, "Memory"), grows by less than 8 MB.
    let (warm, last) = (r.live_kb[2], *r.live_kb.last().unwrap());
    assert!(
        last < warm + 2 * 1024,
        "the live heap grew from {warm} kB to {last} kB: {:?}",
        r.live_kb
    );
    let (warm, last) = (r.rss_kb[2], *r.rss_kb.last().unwrap());
    assert!(
        last < warm + 8 * 1024,
        "memory grew from {warm} kB to {last} kB: {:?}",
        r.rss_kb
    );
}
