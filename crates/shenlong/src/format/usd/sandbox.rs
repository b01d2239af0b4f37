//! Reading a stage in a child process, so that no stage can crash, hang or exhaust the
//! process that asked (the CLI, a server, a Python interpreter, a Ray worker).
//!
//! USD composition follows arcs across files (sublayers, references, payloads, inherits,
//! specializes), and a crafted stage can make a parser recurse without end (an arc cycle,
//! 30,000 nested prims), compose exponentially (each level referencing the next twice),
//! trust a count in a `.usdc` and ask for a petabyte, or reach a `todo!()` in a
//! third-party crate. On Unix the stage is therefore read in a forked child with a memory
//! limit (its address space may grow by [`Budget::memory`] at most) and a time limit
//! ([`Budget::seconds`]); the child sends back only plain data (the prims' names, worlds
//! and points, [`super::wire`]) through a pipe, and the parent decodes it with every
//! length checked. A child that dies — a stack overflow, an abort, an allocation refused
//! — or runs past its time is reported in one line, and the caller goes on.
//!
//! Elsewhere (not Unix) the read runs in-process behind `catch_unwind`.

use super::super::FormatError;

/// The longest a read may be given: a day.
const MAX_SECONDS: u64 = 86_400;

/// What a read may use.
#[derive(Clone, Copy, Debug)]
pub(super) struct Budget {
    /// Wall-clock seconds.
    pub seconds: u64,
    /// Bytes the child's address space may grow by.
    pub memory: u64,
}

impl Budget {
    /// The budget for a stage whose file has `bytes`: 20 s plus 10 s per MiB (an honest
    /// 100,000-object stage is read well within it) unless `SHENLONG_USD_SECONDS` says
    /// otherwise, and 2 GiB plus 64 bytes per byte of file, at most 16 GiB.
    #[must_use]
    pub(super) fn for_bytes(bytes: u64) -> Self {
        let mib = bytes >> 20;
        let seconds = std::env::var("SHENLONG_USD_SECONDS")
            .ok()
            .and_then(|s| s.trim().parse::<u64>().ok())
            .filter(|&s| s > 0)
            .unwrap_or(20 + 10 * mib)
            .min(MAX_SECONDS);
        Self {
            seconds,
            memory: ((2u64 << 30) + 64 * bytes).min(16 << 30),
        }
    }
}

/// Runs `work` under `budget` and returns the bytes it produced.
///
/// # Errors
/// `work`'s own error; or the read died, ran out of memory or time.
#[cfg(unix)]
pub(super) fn run(
    budget: Budget,
    work: impl FnOnce() -> Result<Vec<u8>, FormatError>,
) -> Result<Vec<u8>, FormatError> {
    let mut fds = [0i32; 2];
    // SAFETY: `pipe2` writes two descriptors into the array it is given. Close-on-exec,
    // so that a process another thread starts meanwhile does not hold the pipe open.
    if unsafe { libc::pipe2(fds.as_mut_ptr(), libc::O_CLOEXEC) } != 0 {
        return in_process(work);
    }
    let (read_fd, write_fd) = (fds[0], fds[1]);
    let before = address_space();
    // SAFETY: the child runs only `work` (Rust code that allocates with the system
    // allocator, whose locks glibc makes safe across fork), writes to its pipe and leaves
    // with `_exit`, never returning into the parent's code.
    let pid = unsafe { libc::fork() };
    if pid < 0 {
        // SAFETY: closing descriptors this function opened.
        unsafe {
            libc::close(read_fd);
            libc::close(write_fd);
        }
        return in_process(work);
    }
    if pid == 0 {
        // SAFETY: in the child: close the read end, silence its output (a stack overflow
        // or a panic would print on the user's terminal), limit memory, run, send, leave.
        let write_fd = unsafe {
            libc::close(read_fd);
            // The answer's descriptor above the standard ones (a host started with its
            // stdout closed may have been given 1), before they are redirected.
            let moved = libc::fcntl(write_fd, libc::F_DUPFD_CLOEXEC, 3);
            let write_fd = if moved >= 0 {
                libc::close(write_fd);
                moved
            } else {
                write_fd
            };
            // The host's crash handlers (Python's faulthandler, a debugger's) are the
            // parent's: the child just dies, and the parent says why.
            for signal in [
                libc::SIGSEGV,
                libc::SIGBUS,
                libc::SIGABRT,
                libc::SIGILL,
                libc::SIGFPE,
            ] {
                libc::signal(signal, libc::SIG_DFL);
            }
            let null = libc::open(c"/dev/null".as_ptr(), libc::O_WRONLY);
            if null >= 0 {
                libc::dup2(null, 1);
                libc::dup2(null, 2);
                libc::close(null);
            }
            let limit = before.saturating_add(budget.memory);
            let rl = libc::rlimit {
                rlim_cur: limit as libc::rlim_t,
                rlim_max: limit as libc::rlim_t,
            };
            libc::setrlimit(libc::RLIMIT_AS, &rl);
            write_fd
        };
        // A panic prints nothing (the parent says what failed): the default hook would
        // take the output locks, which a thread of the parent may have held at the fork.
        std::panic::set_hook(Box::new(|_| {}));
        let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(work));
        let message = match result {
            Ok(Ok(bytes)) => frame(0, &bytes),
            Ok(Err(e)) => frame(1, e.to_string().as_bytes()),
            Err(_) => frame(2, b"the USD reader failed on this stage (a panic)"),
        };
        write_all(write_fd, &message);
        // SAFETY: leaving the child without running the parent's destructors or atexit
        // handlers.
        unsafe { libc::_exit(0) }
    }
    // SAFETY: the parent does not write.
    unsafe { libc::close(write_fd) };
    let deadline = std::time::Instant::now() + std::time::Duration::from_secs(budget.seconds);
    let received = read_until(read_fd, deadline, budget.memory);
    // SAFETY: the descriptor is ours.
    unsafe { libc::close(read_fd) };
    let (status, timed_out) = reap(pid, deadline, received.is_none());
    if timed_out {
        return Err(FormatError::too_large(format!(
            "reading the stage took more than {} s (its composition grows without bound, or it is too large; SHENLONG_USD_SECONDS allows more); refused",
            budget.seconds
        )));
    }
    let mut data = received.unwrap_or_default();
    match unframe(&data) {
        Some((0, _)) => {
            // The answer without its 9-byte frame, not copied.
            data.drain(..9);
            Ok(data)
        }
        Some((_, body)) => Err(FormatError::invalid(
            String::from_utf8_lossy(body).into_owned(),
        )),
        None => Err(died(status, budget)),
    }
}

/// Waits for the child until `deadline` (killing it then, or at once when `kill`), and
/// returns its status and whether it ran out of time. Never blocks past the deadline
/// plus the moment a killed process takes to go.
#[cfg(unix)]
fn reap(pid: libc::pid_t, deadline: std::time::Instant, kill: bool) -> (i32, bool) {
    let mut timed_out = kill;
    if kill {
        // SAFETY: the child is ours.
        unsafe { libc::kill(pid, libc::SIGKILL) };
    }
    let mut status = 0;
    loop {
        let flags = if timed_out { 0 } else { libc::WNOHANG };
        // SAFETY: reaping our own child.
        let r = unsafe { libc::waitpid(pid, &mut status, flags) };
        if r == pid {
            return (status, timed_out);
        }
        if r < 0 {
            if std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
                continue;
            }
            return (status, timed_out);
        }
        if std::time::Instant::now() >= deadline {
            // SAFETY: the child is ours.
            unsafe { libc::kill(pid, libc::SIGKILL) };
            timed_out = true;
        } else {
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
    }
}

/// Why a child that sent no answer died, in one line.
#[cfg(unix)]
fn died(status: i32, budget: Budget) -> FormatError {
    let why = if libc::WIFSIGNALED(status) {
        match libc::WTERMSIG(status) {
            libc::SIGSEGV | libc::SIGBUS | libc::SIGABRT => format!(
                "it crashed (a stack overflow from arcs that form a cycle or prims nested too deep, more memory than the {} GiB allowed, or corrupt data)",
                (budget.memory >> 30).max(1)
            ),
            libc::SIGKILL => "it was killed (out of memory)".to_string(),
            s => format!("it died of signal {s}"),
        }
    } else {
        "it ended without an answer".to_string()
    };
    FormatError::invalid(format!("not a USD stage Shenlong can read: reading {why}"))
}

/// A message: its kind, its length and its body.
fn frame(kind: u8, body: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(body.len() + 9);
    out.push(kind);
    out.extend_from_slice(&(body.len() as u64).to_le_bytes());
    out.extend_from_slice(body);
    out
}

/// A whole message, or `None` when it is cut short.
fn unframe(data: &[u8]) -> Option<(u8, &[u8])> {
    let (&kind, rest) = data.split_first()?;
    let len = u64::from_le_bytes(rest.get(..8)?.try_into().ok()?);
    let body = rest.get(8..)?;
    (body.len() as u64 == len).then_some((kind, body))
}

#[cfg(unix)]
fn write_all(fd: i32, mut bytes: &[u8]) {
    while !bytes.is_empty() {
        // SAFETY: writing from a live slice to our descriptor.
        let n = unsafe { libc::write(fd, bytes.as_ptr().cast(), bytes.len()) };
        if n <= 0 {
            return;
        }
        bytes = &bytes[n as usize..];
    }
}

/// Everything the child sends until it closes the pipe, at most `max` bytes (more is cut,
/// and then fails to decode); `None` past `deadline`.
#[cfg(unix)]
fn read_until(fd: i32, deadline: std::time::Instant, max: u64) -> Option<Vec<u8>> {
    let mut out = Vec::new();
    let mut buf = vec![0u8; 1 << 16];
    loop {
        let left = deadline.checked_duration_since(std::time::Instant::now())?;
        let mut poll = libc::pollfd {
            fd,
            events: libc::POLLIN,
            revents: 0,
        };
        let wait = i32::try_from(left.as_millis().min(1000))
            .unwrap_or(1000)
            .max(1);
        // SAFETY: polling one descriptor we own.
        let ready = unsafe { libc::poll(&mut poll, 1, wait) };
        if ready < 0 {
            if std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
                continue;
            }
            return Some(out);
        }
        if ready == 0 {
            continue;
        }
        // SAFETY: reading into a live buffer from our descriptor.
        let n = unsafe { libc::read(fd, buf.as_mut_ptr().cast(), buf.len()) };
        if n < 0 {
            if std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted {
                continue;
            }
            return Some(out);
        }
        if n == 0 {
            return Some(out);
        }
        if (out.len() as u64) < max {
            out.extend_from_slice(&buf[..n as usize]);
        }
    }
}

/// The process's address space now, in bytes (from `/proc/self/statm`; 0 if unknown).
#[cfg(unix)]
fn address_space() -> u64 {
    let pages: u64 = std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(0);
    // SAFETY: sysconf has no preconditions.
    let page = unsafe { libc::sysconf(libc::_SC_PAGESIZE) };
    pages.saturating_mul(u64::try_from(page).unwrap_or(4096))
}

/// The read in this process, a panic turned into an error.
fn in_process(work: impl FnOnce() -> Result<Vec<u8>, FormatError>) -> Result<Vec<u8>, FormatError> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)).unwrap_or_else(|_| {
        Err(FormatError::invalid(
            "the USD reader failed on this stage (a panic)",
        ))
    })
}

/// Not Unix: in-process, panics caught.
#[cfg(not(unix))]
pub(super) fn run(
    _budget: Budget,
    work: impl FnOnce() -> Result<Vec<u8>, FormatError>,
) -> Result<Vec<u8>, FormatError> {
    in_process(work)
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    fn small() -> Budget {
        Budget {
            seconds: 5,
            memory: 256 << 20,
        }
    }

    #[test]
    fn answers_errors_crashes_hogs_and_hangs_come_back_as_one_line() {
        assert_eq!(run(small(), || Ok(vec![1, 2, 3])).unwrap(), [1, 2, 3]);
        let e = run(small(), || Err(FormatError::invalid("no"))).unwrap_err();
        assert_eq!(e.to_string(), "no");
        let e = run(small(), || panic!("boom")).unwrap_err();
        assert!(e.to_string().contains("panic"), "{}", e.to_string());
        // Unbounded recursion: the child's stack overflows, this process goes on.
        #[allow(unconditional_recursion)]
        fn deep(n: u64) -> u64 {
            let pad = [n; 64];
            std::hint::black_box(&pad);
            deep(n + 1) + pad[3]
        }
        let e = run(small(), || Ok(vec![deep(0) as u8])).unwrap_err();
        assert!(e.to_string().contains("crashed"), "{}", e.to_string());
        // A petabyte asked for: refused by the limit.
        let e = run(small(), || {
            let v: Vec<u8> = Vec::with_capacity(1 << 50);
            Ok(v)
        })
        .unwrap_err();
        assert!(e.to_string().contains("crashed"), "{}", e.to_string());
        let e = run(
            Budget {
                seconds: 1,
                memory: 256 << 20,
            },
            || loop {
                std::thread::sleep(std::time::Duration::from_millis(50));
            },
        )
        .unwrap_err();
        assert!(e.to_string().contains("more than 1 s"), "{}", e.to_string());
    }
}
