//! `snooker serve`: the shot lab (the `snooker-server` crate) on a local address: one page and
//! a small JSON API over the engine, scene, planner, rules and player crates. The recordings the page
//! downloads are made by this crate's own exporter ([`crate::record`]), handed to the server as
//! a [`snooker_server::Recorder`], so that the server does not depend on this crate.

use super::{bad_input, failed};
use crate::record;
use snooker_engine::Shot;
use snooker_scene::Scene;
use snooker_server::guard::HostCheck;
use snooker_server::{Config, Limits, Recorder};
use std::net::{IpAddr, SocketAddr};
use std::process::ExitCode;
use std::sync::Arc;

/// Arguments of `snooker serve`.
#[derive(clap::Args)]
pub struct Args {
    /// Port to listen on (0: any free port, printed).
    #[arg(long, default_value_t = 8080)]
    pub port: u16,
    /// Address to listen on: the loopback address unless another is given (the lab has no
    /// accounts; anyone who reaches the address can use it).
    #[arg(long, default_value = "127.0.0.1")]
    pub host: IpAddr,
    /// Open the page in the desktop's browser once listening.
    #[arg(long)]
    pub open: bool,
}

/// The recordings of `snooker simulate --record`, at its default rate.
struct Rerun;

impl Recorder for Rerun {
    fn shot(&self, scene: &Scene, shot: &Shot, rate: f64) -> Result<Vec<u8>, String> {
        let opts = record::RecordOptions {
            rate,
            ..Default::default()
        };
        record::encode(scene, shot, &opts).map_err(|e| e.to_string())
    }
}

/// Opens `url` with the desktop's opener; a failure is only reported.
fn open(url: &str) {
    let opener = if cfg!(target_os = "macos") {
        "open"
    } else if cfg!(windows) {
        "explorer"
    } else {
        "xdg-open"
    };
    if let Err(e) = std::process::Command::new(opener).arg(url).spawn() {
        eprintln!("warning: could not open {url} with {opener}: {e}");
    }
}

/// Runs `snooker serve` until interrupted (Ctrl-C).
pub fn run(args: Args) -> ExitCode {
    let runtime = match tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .build()
    {
        Ok(r) => r,
        Err(e) => return failed(format!("could not start the server's runtime: {e}")),
    };
    let addr = SocketAddr::new(args.host, args.port);
    runtime.block_on(async move {
        let listener = match tokio::net::TcpListener::bind(addr).await {
            Ok(l) => l,
            Err(e) => return bad_input(format!("--host {} --port {}: {e}", args.host, args.port)),
        };
        let local = listener.local_addr().unwrap_or(addr);
        let url = format!("http://{local}/");
        eprintln!("the shot lab is at {url} (Ctrl-C stops it)");
        if !args.host.is_loopback() {
            eprintln!(
                "warning: listening on {}: anyone who reaches it can use the lab",
                args.host
            );
        }
        if args.open {
            open(&url);
        }
        // Bound elsewhere on purpose, the lab is reached by names it cannot know.
        let hosts = if args.host.is_loopback() {
            HostCheck::Loopback
        } else {
            HostCheck::Any
        };
        let app = snooker_server::router(Config {
            limits: Limits::default(),
            recorder: Some(Arc::new(Rerun)),
            hosts,
        });
        let stop = async {
            let _ = tokio::signal::ctrl_c().await;
        };
        match snooker_server::serve(listener, app, stop).await {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => failed(format!("the server stopped: {e}")),
        }
    })
}
