"""Runs one untrusted command with a wall-clock limit, resource limits and, where the
kernel allows it, inside a bubblewrap sandbox.

Everything the grader knows about isolation lives here, so the rest of the grader only asks
"run this, with these folders readable and this one writable" and reads a RunResult.

Isolation, strongest first:
  bwrap   Debian's bubblewrap in new user, pid, network, IPC and UTS namespaces: no network,
          only /usr (and the /lib links) plus the folders the caller names are visible, a
          private /tmp. The resource limits are set inside the namespace, where RLIMIT_NPROC
          counts the sandbox's own processes, not all of the grader's uid (a desktop session
          alone has more than 64). It never binds root, so when the grader runs as root every
          command runs as a fresh unprivileged uid of its own, *outside* the namespace too;
          a fresh uid also cannot signal or read another run.
  rlimits no namespaces (bwrap missing or user namespaces disabled, as in many Docker
          containers): the same resource limits and a scratch working folder, as a fresh
          uid when the grader is root; every process left with that uid is killed
          afterwards. The code can read any world-readable file, so the grader prints a
          warning.
"""
from dataclasses import dataclass, field, replace
import itertools
import os
import selectors
import shutil
import signal
import subprocess
import time

FRESH_UID_BASE = 1_600_000_000   # far above real users and the usual subuid ranges
_counter = itertools.count()
SAFE_PATH = "/usr/local/bin:/usr/bin:/bin"


@dataclass
class Limits:
    wall_seconds: float = 10.0
    memory_bytes: int = 1 << 30          # address space; ignored for sanitizer builds
    file_bytes: int = 16 << 20           # largest file the command may write (the report)
    processes: int = 64                  # per sandbox (bwrap) or per uid (rlimits)
    output_bytes: int = 1 << 20          # more output than this is a flood: the run is stopped
    keep_output_bytes: int = 64 << 10    # how much of stdout+stderr is kept for feedback
    address_space_limit: bool = True
    disk_bytes: int | None = None        # total the command may leave in its writable folder


@dataclass
class RunResult:
    returncode: int | None = None        # exit status, or None when killed by a signal
    signal: int | None = None
    timed_out: bool = False
    flooded: bool = False
    disk_full: bool = False              # wrote more than disk_bytes into its writable folder
    output: bytes = b""
    output_total: int = 0
    seconds: float = 0.0
    error: str | None = None              # the command could not be started at all

    @property
    def ok(self):
        return (self.error is None and not self.timed_out and not self.flooded and not self.disk_full
                and self.returncode == 0)


@dataclass
class Sandbox:
    mode: str                      # "bwrap" or "rlimits"
    fresh_uids: bool               # each run as its own unprivileged uid (the grader is root)
    warning: str | None = None
    bwrap: str | None = None
    _system_binds: list = field(default_factory=list)

    @property
    def description(self):
        who = (f"a fresh unprivileged uid per run ({FRESH_UID_BASE}+)" if self.fresh_uids
               else f"uid {os.getuid()}")
        if self.mode == "bwrap":
            return f"bubblewrap sandbox (no network, private filesystem view), running as {who}"
        return f"separate process with resource limits only, running as {who}"

    def prepare_writable(self, path):
        """A folder the sandboxed runs will write to (each run then takes it over)."""
        os.chmod(path, 0o755)

    def _next_uid(self):
        return FRESH_UID_BASE + (os.getpid() % 100_000) * 10_000 + next(_counter) % 10_000

    def run(self, argv, *, readable=(), writable=None, cwd=None, limits=None, stdin_fd=None, pass_fds=()):
        """Runs argv; `readable` folders are visible read-only at their own paths, `writable`
        (one folder) read-write; cwd defaults to `writable`. `stdin_fd` becomes its standard
        input and `pass_fds` stay open in it at their numbers; both are handed over: closed
        here once the command has started (so that its end of a pipe is its alone)."""
        limits = limits or Limits()
        uid = self._next_uid() if self.fresh_uids else None
        if self.mode != "bwrap" and uid is None:
            # Without a namespace or a uid of its own, RLIMIT_NPROC counts every process and
            # thread of the grader's user (a desktop session alone has hundreds): the budget
            # goes on top of what the user already runs, or every compile would fail.
            limits = replace(limits, processes=limits.processes + _tasks_of(os.getuid()))
        cwd = cwd or writable or "/"
        # Inside bwrap the limits are set after the user namespace exists, so RLIMIT_NPROC
        # counts this sandbox's processes only, not every process of the grader's uid.
        command = self._wrap(_prlimit_prefix(limits) + list(argv), readable, writable, cwd)
        if uid is not None and writable:
            os.chown(writable, uid, uid)
        try:
            return _supervise(command, cwd if self.mode != "bwrap" else "/", limits, uid, stdin_fd, pass_fds,
                              watch=writable if limits.disk_bytes else None)
        finally:
            if uid is not None:
                _kill_uid(uid)

    def _wrap(self, argv, readable, writable, cwd):
        if self.mode != "bwrap":
            return argv
        args = [self.bwrap, "--unshare-all", "--die-with-parent", "--new-session", "--clearenv",
                "--setenv", "PATH", SAFE_PATH, "--setenv", "LANG", "C.UTF-8", "--setenv", "HOME", "/tmp"]
        args += self._system_binds
        args += ["--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"]
        for path in readable:
            args += ["--ro-bind", str(path), str(path)]
        if writable:
            args += ["--bind", str(writable), str(writable)]
        args += ["--chdir", str(cwd), "--"]
        return args + argv


def _system_binds():
    """/usr read-only, and /bin, /lib... as the links (merged /usr) or folders they are."""
    binds = ["--ro-bind", "/usr", "/usr"]
    for name in ("bin", "sbin", "lib", "lib32", "lib64", "libx32"):
        path = "/" + name
        if os.path.islink(path):
            binds += ["--symlink", os.readlink(path), path]
        elif os.path.isdir(path):
            binds += ["--ro-bind", path, path]
    # The dynamic loader's cache and the C++ runtime's locale settings; nothing secret.
    for path in ("/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives"):
        if os.path.exists(path):
            binds += ["--ro-bind", path, path]
    return binds


def _prlimit_prefix(limits):
    """Resource limits through util-linux prlimit, applied between fork and exec of the
    command, so the grader needs no preexec_fn (unsafe in a threaded program)."""
    cpu = max(1, int(limits.wall_seconds) + 1)
    args = [PRLIMIT, f"--cpu={cpu}", f"--fsize={limits.file_bytes}", f"--nproc={limits.processes}",
            "--core=0"]
    if limits.address_space_limit:
        args.append(f"--as={limits.memory_bytes}")
    return args + ["--"]


PRLIMIT = shutil.which("prlimit") or "/usr/bin/prlimit"


def _pids_of(uid):
    """The pids of the processes running as `uid` now (some may be gone when used)."""
    pids = []
    for entry in os.listdir("/proc"):
        try:
            if entry.isdigit() and os.stat(f"/proc/{entry}").st_uid == uid:
                pids.append(int(entry))
        except OSError:
            continue
    return pids


def _tasks_of(uid):
    """Processes and threads now running as `uid`: what RLIMIT_NPROC counts."""
    count = 0
    for pid in _pids_of(uid):
        try:
            count += len(os.listdir(f"/proc/{pid}/task"))
        except OSError:
            continue
    return count


def _disk_used(folder):
    used = 0
    for root, dirs, files in os.walk(folder):
        for name in files + dirs:
            try:
                used += os.lstat(os.path.join(root, name)).st_blocks * 512
            except OSError:
                continue
    return used


def _supervise(command, cwd, limits, run_as, stdin_fd=None, pass_fds=(), watch=None):
    """Starts the command in its own session, keeps at most keep_output_bytes of its output,
    and kills the whole process group on timeout or flood. Never blocks past the deadline."""
    result = RunResult()
    start = time.monotonic()
    env = {"PATH": SAFE_PATH, "LANG": "C.UTF-8", "HOME": "/tmp"}
    try:
        process = subprocess.Popen(command, cwd=cwd, env=env,
                                   stdin=subprocess.DEVNULL if stdin_fd is None else stdin_fd,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True,
                                   close_fds=True, pass_fds=tuple(pass_fds),
                                   user=run_as, group=run_as, extra_groups=[] if run_as is not None else None)
    except OSError as error:
        result.error = f"could not start {command[0]}: {error}"
        return result
    finally:
        for handed in ([stdin_fd] if stdin_fd is not None else []) + list(pass_fds):
            os.close(handed)
    kept = bytearray()
    deadline = start + limits.wall_seconds
    selector = selectors.DefaultSelector()
    selector.register(process.stdout, selectors.EVENT_READ)
    descriptor = process.stdout.fileno()
    try:
        open_pipe = True
        while open_pipe:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                result.timed_out = process.poll() is None
                break
            if watch and _disk_used(watch) > limits.disk_bytes:
                result.disk_full = True
                break
            for _ in selector.select(timeout=min(remaining, 0.1 if watch else 0.5)):
                chunk = os.read(descriptor, 65536)
                if not chunk:
                    open_pipe = False
                    break
                result.output_total += len(chunk)
                if len(kept) < limits.keep_output_bytes:
                    kept += chunk[: limits.keep_output_bytes - len(kept)]
                if result.output_total > limits.output_bytes:
                    result.flooded = True
                    open_pipe = False
                    break
        if result.timed_out or result.flooded or result.disk_full:
            _kill_group(process)
        # The pipe is closed (or we gave up on it); the process itself must end soon.
        try:
            process.wait(timeout=max(0.1, deadline - time.monotonic()) if not result.timed_out else 2)
        except subprocess.TimeoutExpired:
            result.timed_out = True
            _kill_group(process)
            process.wait(timeout=5)
    finally:
        selector.close()
        process.stdout.close()
        if process.poll() is None:
            _kill_group(process)
        # Children left in the group (rlimits mode, or a command that closed its output)
        # must not outlive the run.
        _kill_group(process, quiet=True)
    result.seconds = time.monotonic() - start
    result.output = bytes(kept)
    code = process.returncode
    if code is not None and code < 0:
        result.signal = -code
    else:
        result.returncode = code
    # bwrap reports a signal that killed the command as exit status 128 + signal.
    if result.returncode is not None and result.returncode > 128 and result.returncode - 128 < 65:
        result.signal = result.returncode - 128
        result.returncode = None
    return result


def _kill_group(process, quiet=False):
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    if not quiet:
        try:
            process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            pass


def _kill_uid(uid):
    """Kills every process still running as `uid`: children that left the process group
    (setsid) survive a killpg when there is no pid namespace to tear down. A few passes
    without waiting: a process forking while we kill is bounded by RLIMIT_NPROC."""
    for _ in range(3):
        pids = _pids_of(uid)
        if not pids:
            return
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                continue


def _probe(sandbox):
    result = sandbox.run(["/bin/sh", "-c", "echo ok"], limits=Limits(wall_seconds=10))
    return result.ok and result.output.strip() == b"ok"


def detect(allow_bwrap=True):
    """The strongest isolation that works on this machine, checked by running a command."""
    root = os.getuid() == 0
    bwrap = shutil.which("bwrap")
    if allow_bwrap and bwrap:
        for fresh in ([True, False] if root else [False]):
            sandbox = Sandbox("bwrap", fresh, bwrap=bwrap, _system_binds=_system_binds())
            if _probe(sandbox):
                if root and not fresh:
                    sandbox.warning = ("bubblewrap works only as root here, so the process limit does not bind: "
                                       "a fork loop is stopped by the time limit only.")
                return sandbox
    sandbox = Sandbox("rlimits", root)
    reason = "bubblewrap is not installed" if not bwrap else "bubblewrap cannot create namespaces here"
    if not allow_bwrap:
        reason = "bubblewrap was switched off (--no-bwrap)"
    sandbox.warning = (f"WARNING: weaker isolation: {reason}. Student code runs as a separate process with "
                       "resource limits only; it can read world-readable files (including solutions/ and tests/) "
                       "and reach the network.")
    return sandbox
