//! The `exactlti` command: see `exactlti --help` and ../shared/CLI-CONTRACT.md.
use std::io::Write;

/// Every allocation is counted against `--max-memory` (over it: one line, exit 2).
#[global_allocator]
static ALLOC: exactlti::cli::memory::Counting = exactlti::cli::memory::Counting;

fn main() {
    exactlti::cli::memory::set_max_memory_mib(exactlti::cli::memory::DEFAULT_MAX_MEMORY_MIB);
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        // never a second panic from a closed stderr
        let _ = writeln!(std::io::stderr(), "exactlti: internal failure: {msg}");
    }));
    let cli = match exactlti::cli::Cli::try_parse_args(std::env::args_os()) {
        Ok(c) => c,
        // contract: one line on stderr, exit 2 (help and version: exit 0)
        Err(e) => std::process::exit(exactlti::cli::report_parse_error(&e)),
    };
    std::process::exit(exactlti::cli::run(cli));
}
