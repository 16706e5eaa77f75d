//! The memory budget of the command line (`--max-memory MIB`, default
//! [`DEFAULT_MAX_MEMORY_MIB`]): a counting global allocator.
//!
//! Identity kept: `in_use()` = bytes allocated − bytes freed through the Rust allocator (every
//! allocation of the program: exact arithmetic, nalgebra, serde, the report). An allocation
//! that would take `in_use()` past the budget, or one the system refuses (an address-space
//! limit such as `ulimit -v`), is not an abort: the program writes one line on stderr
//! (`exactlti: out of memory: ... (--max-memory N MiB)`) and exits with status 2, the status of
//! "a request that cannot be met".
//!
//! Why an allocator and not an estimate made before the work: the size of exact intermediate
//! results depends on the structure of the input far more than on its size and bit lengths
//! (a 2900 x 2900 companion matrix has a small characteristic polynomial, a dense 600 x 600
//! matrix of 50-digit integers has fraction-free pivots of 100 000 bits), so any estimate
//! refuses feasible inputs or lets infeasible ones through. The allocator sees the real
//! demand of every command, including the ones added later. Long sweeps stream their rows
//! (`sweep`), so that their memory does not grow with `--points`.
//!
//! The binary installs [`Counting`] as its global allocator; the library and the Python
//! package do not (in them the budget is inactive).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// Default budget in MiB: a laptop with 4 GB of memory keeps room for the system.
pub const DEFAULT_MAX_MEMORY_MIB: u64 = 2048;

static IN_USE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);
static LIMIT: AtomicUsize = AtomicUsize::new(usize::MAX);
/// Set by the first refusal: later allocations (the message, other threads until the exit)
/// pass unchecked.
static TRIPPED: AtomicBool = AtomicBool::new(false);

/// Sets the budget (MiB); 0 or a value beyond the address space means no budget.
pub fn set_max_memory_mib(mib: u64) {
    let bytes = mib
        .checked_mul(1 << 20)
        .and_then(|b| usize::try_from(b).ok());
    LIMIT.store(
        bytes.filter(|&b| b > 0).unwrap_or(usize::MAX),
        Ordering::Relaxed,
    );
}

/// Bytes currently allocated through [`Counting`] (0 when it is not the global allocator).
pub fn in_use() -> usize {
    IN_USE.load(Ordering::Relaxed)
}

/// The largest [`in_use`] seen so far.
pub fn peak() -> usize {
    PEAK.load(Ordering::Relaxed)
}

/// The counting allocator (see the module docs): the system allocator plus a running total.
pub struct Counting;

/// Takes `size` more bytes into the count; `false` when that passes the budget (the count is
/// left unchanged then).
fn admit(size: usize) -> bool {
    let before = IN_USE.fetch_add(size, Ordering::Relaxed);
    let now = before.saturating_add(size);
    if now > LIMIT.load(Ordering::Relaxed) && !TRIPPED.load(Ordering::Relaxed) {
        IN_USE.fetch_sub(size, Ordering::Relaxed);
        return false;
    }
    // a plain load first: most allocations do not raise the peak, and `fetch_max` is a
    // compare-and-swap loop on every call
    if now > PEAK.load(Ordering::Relaxed) {
        PEAK.fetch_max(now, Ordering::Relaxed);
    }
    true
}

fn release(size: usize) {
    IN_USE.fetch_sub(size, Ordering::Relaxed);
}

/// A fixed buffer for the refusal line (formatting it must not allocate).
struct Line {
    buf: [u8; 320],
    len: usize,
}

impl std::fmt::Write for Line {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        let room = self.buf.len() - self.len;
        let n = s.len().min(room);
        self.buf[self.len..self.len + n].copy_from_slice(&s.as_bytes()[..n]);
        self.len += n;
        Ok(())
    }
}

/// Writes the refusal line and ends the process with status 2 (no unwinding: an allocator
/// must not unwind; no flush of stdout: a partial report is not printed as if complete).
#[cold]
fn refuse(size: usize, by_system: bool) -> ! {
    use std::fmt::Write as _;
    if TRIPPED.swap(true, Ordering::SeqCst) {
        // another thread is already refusing: wait for its exit
        loop {
            std::thread::sleep(std::time::Duration::from_secs(60));
        }
    }
    let mib = |b: usize| b as f64 / (1u64 << 20) as f64;
    let limit = LIMIT.load(Ordering::Relaxed);
    let mut line = Line {
        buf: [0; 320],
        len: 0,
    };
    let _ = if by_system {
        writeln!(
            line,
            "exactlti: out of memory: the system refused {:.0} MiB with {:.0} MiB in use (an address-space or memory limit); the problem is too large for this machine",
            mib(size),
            mib(in_use())
        )
    } else {
        writeln!(
            line,
            "exactlti: out of memory: the computation needs more than --max-memory {:.0} MiB ({:.0} MiB in use, {:.0} MiB more asked for); raise --max-memory or give a smaller problem",
            mib(limit),
            mib(in_use()),
            mib(size)
        )
    };
    {
        use std::io::Write as _;
        let _ = std::io::stderr().write_all(&line.buf[..line.len]);
    }
    exit_now(2)
}

#[cfg(unix)]
fn exit_now(code: i32) -> ! {
    // SAFETY: `_exit` ends the process at once; nothing runs after it.
    unsafe { libc::_exit(code) }
}

#[cfg(not(unix))]
fn exit_now(code: i32) -> ! {
    std::process::exit(code)
}

// SAFETY: every method forwards to `System` with the same layout and pointer; the count is
// bookkeeping only. A refused allocation never returns (the process exits), so no caller
// sees a null pointer from the budget.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if !admit(layout.size()) {
            refuse(layout.size(), false);
        }
        // SAFETY: forwarded with the caller's layout (non-zero size, per the trait contract).
        let p = unsafe { System.alloc(layout) };
        if p.is_null() {
            release(layout.size());
            refuse(layout.size(), true);
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if !admit(layout.size()) {
            refuse(layout.size(), false);
        }
        // SAFETY: as in `alloc`.
        let p = unsafe { System.alloc_zeroed(layout) };
        if p.is_null() {
            release(layout.size());
            refuse(layout.size(), true);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` was allocated by `System` with `layout` (through this allocator).
        unsafe { System.dealloc(ptr, layout) };
        release(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let old = layout.size();
        if new_size > old && !admit(new_size - old) {
            refuse(new_size - old, false);
        }
        // SAFETY: `ptr` and `layout` come from this allocator; `new_size` per the contract.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if p.is_null() {
            if new_size > old {
                release(new_size - old);
            }
            refuse(new_size, true);
        }
        if new_size < old {
            release(old - new_size);
        }
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn admit_counts_and_refuses_past_the_limit_without_counting() {
        // the test binary does not install `Counting`: the count is driven by hand
        let base = in_use();
        set_max_memory_mib(1);
        assert!(admit(1000));
        assert_eq!(in_use(), base + 1000);
        assert!(!admit(1 << 20));
        assert_eq!(in_use(), base + 1000, "a refused request is not counted");
        release(1000);
        assert_eq!(in_use(), base);
        set_max_memory_mib(0);
        assert!(admit(1 << 30));
        release(1 << 30);
        assert!(peak() >= base + (1 << 30));
    }
}
