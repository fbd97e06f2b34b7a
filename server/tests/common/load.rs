#![allow(dead_code)] // Shared by the load test and the load example: each uses a part.
//! The load driver shared by the load example (figures) and the load test (no errors, memory
//! flat): the lab served on a loopback port in this process, and rounds of concurrent
//! clients, each on its own connection, asking for simulations and plans.
//!
//! The process's allocations are counted ([`Counting`], this binary's global allocator), so
//! that a run tells the heap the program holds (live bytes) apart from the resident memory the
//! allocator keeps from the system: a leak grows the first, allocator retention only the second.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicI64, Ordering};

/// The system allocator, counting the bytes live (allocated and not yet freed).
pub struct Counting;

static LIVE: AtomicI64 = AtomicI64::new(0);

// SAFETY: every call is passed to the system allocator unchanged; only a counter is added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            LIVE.fetch_add(layout.size() as i64, Ordering::Relaxed);
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            LIVE.fetch_add(layout.size() as i64, Ordering::Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        LIVE.fetch_sub(layout.size() as i64, Ordering::Relaxed);
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            LIVE.fetch_add(new_size as i64 - layout.size() as i64, Ordering::Relaxed);
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Bytes allocated and not freed, kB.
pub fn live_kb() -> u64 {
    (LIVE.load(Ordering::Relaxed).max(0) / 1024) as u64
}

/// Hands the allocator's free memory back to the system (glibc's `malloc_trim`), so that the
/// resident size measured next is what the program holds plus what cannot be returned.
pub fn trim() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    {
        unsafe extern "C" {
            fn malloc_trim(pad: usize) -> i32;
        }
        // SAFETY: malloc_trim takes a size and only releases free memory.
        unsafe {
            malloc_trim(0);
        }
    }
}

use http_body_util::{BodyExt, Full};
use hyper::body::Bytes;
use serde_json::{Value, json};
use snooker_server::{Config, Limits, router};
use std::net::SocketAddr;
use std::time::{Duration, Instant};

/// What a load run saw.
#[derive(Debug, Default)]
pub struct Report {
    /// Simulate requests answered 200.
    pub simulations: usize,
    /// Plans that ended done.
    pub plans: usize,
    /// Every failure, said.
    pub errors: Vec<String>,
    /// Latency of each simulation, s.
    pub simulate_times: Vec<f64>,
    /// Time from a plan's request to its job's end, s.
    pub plan_times: Vec<f64>,
    /// Resident memory of the process after each round, kB.
    pub rss_kb: Vec<u64>,
    /// Heap live (allocated, not freed) after each round, kB.
    pub live_kb: Vec<u64>,
    /// Wall time of the run, s.
    pub wall: f64,
}

/// Resident memory of this process, kB (Linux; 0 elsewhere).
pub fn rss_kb() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmRSS:"))
                .and_then(|l| l.split_whitespace().nth(1).and_then(|v| v.parse().ok()))
        })
        .unwrap_or(0)
}

/// One request on a fresh connection: status and JSON body.
async fn request(
    addr: SocketAddr,
    method: &str,
    path: &str,
    body: Option<&Value>,
) -> Result<(u16, Value), String> {
    let stream = tokio::net::TcpStream::connect(addr)
        .await
        .map_err(|e| e.to_string())?;
    let io = hyper_util::rt::TokioIo::new(stream);
    let (mut sender, conn) = hyper::client::conn::http1::handshake(io)
        .await
        .map_err(|e| e.to_string())?;
    tokio::spawn(conn);
    let bytes = body.map(|b| b.to_string()).unwrap_or_default();
    let req = hyper::Request::builder()
        .method(method)
        .uri(path)
        .header("host", addr.to_string())
        .header("content-type", "application/json")
        .body(Full::new(Bytes::from(bytes)))
        .map_err(|e| e.to_string())?;
    let resp = sender.send_request(req).await.map_err(|e| e.to_string())?;
    let status = resp.status().as_u16();
    let body = resp
        .into_body()
        .collect()
        .await
        .map_err(|e| e.to_string())?
        .to_bytes();
    let v = serde_json::from_slice(&body).map_err(|e| format!("{path}: not JSON: {e}"))?;
    Ok((status, v))
}

fn scene(text: &str) -> Value {
    serde_json::to_value(toml::from_str::<toml::Table>(text).expect("scene")).expect("json")
}

/// The shots asked for: each built-in scene with its own strike, and the break-off.
fn shots() -> Vec<Value> {
    let mut out: Vec<Value> = [
        include_str!("../../../scenes/cut-30.toml"),
        include_str!("../../../scenes/screw.toml"),
        include_str!("../../../scenes/three-cushion.toml"),
        include_str!("../../../scenes/one-cushion.toml"),
    ]
    .iter()
    .map(|t| scene(t))
    .collect();
    let mut brk = scene("layout = \"break-off\"");
    brk["cue"] =
        json!({"ball": "cue", "speed": 7.0, "aim": 0.02, "offset": [0.0, 0.0], "elevation": 0.0});
    out.push(brk);
    out
}

async fn simulate(addr: SocketAddr, scene: Value) -> Result<f64, String> {
    let t = Instant::now();
    let (s, v) = request(
        addr,
        "POST",
        "/api/simulate",
        Some(&json!({"scene": scene})),
    )
    .await?;
    if s != 200 {
        return Err(format!("simulate: HTTP {s}: {v}"));
    }
    Ok(t.elapsed().as_secs_f64())
}

async fn plan(addr: SocketAddr, samples: usize) -> Result<f64, String> {
    let t = Instant::now();
    let req = json!({
        "scene": scene(include_str!("../../../scenes/chapter7-example.toml")),
        "pot": "red", "pocket": "middle-left", "target": [1.2, 0.6],
        "samples": samples, "alternatives": 1,
    });
    let (s, v) = request(addr, "POST", "/api/plan", Some(&req)).await?;
    if s != 202 {
        return Err(format!("plan: HTTP {s}: {v}"));
    }
    let id = v["id"].as_u64().ok_or("plan: no job id")?;
    loop {
        tokio::time::sleep(Duration::from_millis(50)).await;
        let (s, v) = request(addr, "GET", &format!("/api/jobs/{id}"), None).await?;
        if s != 200 {
            return Err(format!("job {id}: HTTP {s}: {v}"));
        }
        match v["state"].as_str() {
            Some("queued" | "running") => continue,
            Some("done") => return Ok(t.elapsed().as_secs_f64()),
            _ => return Err(format!("job {id}: {v}")),
        }
    }
}

/// Serves the lab with `limits` on a loopback port and runs `rounds` rounds of `clients`
/// concurrent simulations and `plans` concurrent plans of `samples` samples each; with `trim`,
/// the allocator's free memory is handed back to the system after each round.
pub async fn run(
    limits: Limits,
    clients: usize,
    plans: usize,
    samples: usize,
    rounds: usize,
    trim: bool,
) -> Report {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let addr = listener.local_addr().expect("addr");
    let server = tokio::spawn(async move {
        axum::serve(
            listener,
            router(Config {
                limits,
                recorder: None,
                hosts: Default::default(),
            }),
        )
        .await
        .expect("serve");
    });
    let shots = shots();
    let mut report = Report::default();
    let start = Instant::now();
    for _ in 0..rounds {
        let mut sims = Vec::new();
        for c in 0..clients {
            sims.push(tokio::spawn(simulate(addr, shots[c % shots.len()].clone())));
        }
        let mut jobs = Vec::new();
        for _ in 0..plans {
            jobs.push(tokio::spawn(plan(addr, samples)));
        }
        for s in sims {
            match s.await {
                Ok(Ok(t)) => {
                    report.simulations += 1;
                    report.simulate_times.push(t);
                }
                Ok(Err(e)) => report.errors.push(e),
                Err(e) => report.errors.push(e.to_string()),
            }
        }
        for j in jobs {
            match j.await {
                Ok(Ok(t)) => {
                    report.plans += 1;
                    report.plan_times.push(t);
                }
                Ok(Err(e)) => report.errors.push(e),
                Err(e) => report.errors.push(e.to_string()),
            }
        }
        if trim {
            self::trim();
        }
        report.rss_kb.push(rss_kb());
        report.live_kb.push(live_kb());
    }
    report.wall = start.elapsed().as_secs_f64();
    server.abort();
    report
}

/// The `q` quantile of `v` (sorted in place).
pub fn quantile(v: &mut [f64], q: f64) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * q).round() as usize]
}
