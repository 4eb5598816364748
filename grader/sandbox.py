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
from __future__ import annotations  # `X | None` annotations on Python 3.8 and 3.9
from dataclasses import dataclass, field, replace
import itertools
import os
import selectors
import shutil
import signal
import subprocess
import sys
import threading
import time

FRESH_UID_BASE = 1_600_000_000   # far above real users and the usual subuid ranges
_counter = itertools.count()
_group_counter = itertools.count()
# Folders every user may write to on a normal machine: without a private /tmp, what a run's
# uid leaves there is removed after the run (and counts towards its disk limit meanwhile).
SHARED_WRITABLE = ("/tmp", "/var/tmp", "/dev/shm", "/dev/mqueue", "/run/lock")
# Every command the grader started and has not seen end, so that an interrupted batch can
# stop them all (see stop_all).
_live = set()
_live_lock = threading.Lock()
stopping = threading.Event()   # set when the batch is interrupted: no command starts any more
SAFE_PATH = "/usr/local/bin:/usr/bin:/bin"


@dataclass
class Limits:
    wall_seconds: float = 10.0
    memory_bytes: int = 1 << 30          # address space per process; memory held by the run as a whole
                                         # when it has a uid of its own (ignored for sanitizer builds)
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
    memory_full: bool = False            # its processes together held more than memory_bytes
    output: bytes = b""
    output_total: int = 0
    seconds: float = 0.0
    error: str | None = None              # the command could not be started at all

    @property
    def ok(self):
        return (self.error is None and not self.timed_out and not self.flooded and not self.disk_full
                and not self.memory_full and self.returncode == 0)


@dataclass
class Sandbox:
    mode: str                      # "bwrap" or "rlimits"
    fresh_uids: bool               # each run as its own unprivileged uid (the grader is root)
    warning: str | None = None
    bwrap: str | None = None
    _system_binds: list = field(default_factory=list)
    sized_tmp: bool = True         # bubblewrap 0.8 or newer: its /tmp and /dev/shm can be sized

    @property
    def description(self):
        who = (f"a fresh unprivileged uid per run ({FRESH_UID_BASE}+)" if self.fresh_uids
               else f"uid {os.getuid()}")
        if self.mode == "bwrap":
            return f"bubblewrap sandbox (no network, private filesystem view), running as {who}"
        return f"separate process with resource limits only, running as {who}"

    @property
    def shares_tmp(self):
        """Runs see the machine's /tmp, /dev/shm... (no namespace): what one leaves there
        another could read while both run."""
        return self.mode != "bwrap"

    def new_group(self):
        """A fresh gid for one submission's runs (None when runs have no uid of their own):
        its folders are open to that group only, so no other submission's runs can read them."""
        if not self.fresh_uids:
            return None
        return FRESH_UID_BASE + (os.getpid() % 100_000) * 10_000 + next(_group_counter) % 10_000

    def private_folder(self, path, group=None):
        """Makes `path` (a folder of the grader's) reachable by `group`'s runs only."""
        if group is not None:
            os.chown(path, os.getuid(), group)
            os.chmod(path, 0o750)
        else:
            os.chmod(path, 0o700)

    def _next_uid(self):
        return FRESH_UID_BASE + (os.getpid() % 100_000) * 10_000 + next(_counter) % 10_000

    def run(self, argv, *, readable=(), writable=None, cwd=None, limits=None, stdin_fd=None, pass_fds=(),
            group=None):
        """Runs argv; `readable` folders are visible read-only at their own paths, `writable`
        (one folder) read-write; cwd defaults to `writable`. `stdin_fd` becomes its standard
        input and `pass_fds` stay open in it at their numbers; both are handed over: closed
        here once the command has started (so that its end of a pipe is its alone).

        With fresh uids the command runs as a new uid in `group` (see new_group); `writable`
        is its alone (0700) while it runs, and afterwards the grader's again, readable by
        the group; every process of the uid is killed and, without a private /tmp, every
        file it left in the shared folders removed."""
        limits = limits or Limits()
        uid = self._next_uid() if self.fresh_uids else None
        gid = (group if group is not None else uid) if uid is not None else None
        if self.mode != "bwrap" and uid is None:
            # Without a namespace or a uid of its own, RLIMIT_NPROC counts every process and
            # thread of the grader's user (a desktop session alone has hundreds): the budget
            # goes on top of what the user already runs, or every compile would fail.
            limits = replace(limits, processes=limits.processes + _tasks_of(os.getuid()))
        cwd = cwd or writable or "/"
        # Inside bwrap the limits are set after the user namespace exists, so RLIMIT_NPROC
        # counts this sandbox's processes only, not every process of the grader's uid.
        command = self._wrap(_prlimit_prefix(limits) + list(argv), readable, writable, cwd, limits)
        if uid is not None and writable:
            os.chown(writable, uid, gid)
            os.chmod(writable, 0o700)
        env = {"PATH": SAFE_PATH, "LANG": "C.UTF-8", "HOME": "/tmp"}
        if self.mode != "bwrap" and writable:
            env.update(HOME=str(writable), TMPDIR=str(writable))  # its own, not the machine's /tmp
        try:
            return _supervise(command, cwd if self.mode != "bwrap" else "/", limits, (uid, gid) if uid else None,
                              env, stdin_fd, pass_fds, watch=writable if limits.disk_bytes else None,
                              shared=self.shares_tmp and uid is not None)
        finally:
            if uid is not None:
                _kill_uid(uid, gid)
                if self.shares_tmp:
                    _remove_left_behind(uid)
                if writable:
                    _take_back(writable, gid)

    def _wrap(self, argv, readable, writable, cwd, limits):
        if self.mode != "bwrap":
            return argv
        args = [self.bwrap, "--unshare-all", "--die-with-parent", "--new-session", "--clearenv",
                "--setenv", "PATH", SAFE_PATH, "--setenv", "LANG", "C.UTF-8", "--setenv", "HOME", "/tmp"]
        args += self._system_binds
        # /tmp and /dev/shm are memory: sized, or a run could fill the machine's RAM there.
        size = ["--size", str(limits.disk_bytes or TMP_BYTES_WITHOUT_DISK_LIMIT)] if self.sized_tmp else []
        args += ["--proc", "/proc", "--dev", "/dev", *size, "--tmpfs", "/tmp", *size, "--tmpfs", "/dev/shm"]
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
TMP_BYTES_WITHOUT_DISK_LIMIT = 512 << 20   # the compiler's temporary files


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


# util-linux's setpriv starts a command as another user. Python can change the user itself
# between fork and exec, but then it must fork the whole grader, page tables and all (about
# 8 ms of processor time a run); through setpriv it starts the command with vfork.
SETPRIV = shutil.which("setpriv", path="/usr/bin:/bin")
KILL = shutil.which("kill", path="/usr/bin:/bin")


def _as_user(command, uid, gid):
    """(argv, uid, gid) that start `command` as `uid` in group `gid` with no supplementary
    groups: through setpriv where there is one (and the uid and gid are then done with)."""
    if uid is None or SETPRIV is None:
        return command, uid, gid
    return [SETPRIV, f"--reuid={uid}", f"--regid={gid}", "--clear-groups", "--", *command], None, None


def _identity(uid, gid):
    """Popen's arguments that start the command with umask 077 and, when `uid` is given, as
    that user and group with no supplementary groups. Python 3.9 and newer do it in the
    child without running Python there (umask, user, group, extra_groups); on 3.8 a preexec_fn
    makes the same calls, in the order that keeps the right to make them (groups, group, user)."""
    if sys.version_info >= (3, 9):
        if uid is None:
            return {"umask": 0o077}
        return {"umask": 0o077, "user": uid, "group": gid, "extra_groups": []}

    def become():
        os.umask(0o077)
        if uid is not None:
            os.setgroups([])
            os.setgid(gid)
            os.setuid(uid)
    return {"preexec_fn": become}


def _supervise(command, cwd, limits, run_as, env, stdin_fd=None, pass_fds=(), watch=None, shared=False):
    """Starts the command in its own session, keeps at most keep_output_bytes of its output,
    and kills the whole process group on timeout, flood, disk or memory limit. Never blocks
    past the deadline. `run_as` is (uid, gid) or None; with a uid of its own the memory of
    all its processes together is watched, and with `shared`, its files in the shared folders
    count towards its disk limit."""
    result = RunResult()
    start = time.monotonic()
    uid, gid = run_as if run_as else (None, None)
    try:
        if stopping.is_set():
            raise OSError("the grader was interrupted")
        # umask 077: what it writes is its own; new session: a Ctrl-C in the grader's
        # terminal reaches the grader only, which decides what to stop.
        started_as = _as_user(command, uid, gid)
        process = subprocess.Popen(started_as[0], cwd=cwd, env=env,
                                   stdin=subprocess.DEVNULL if stdin_fd is None else stdin_fd,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True,
                                   close_fds=True, pass_fds=tuple(pass_fds), **_identity(*started_as[1:]))
    except OSError as error:
        result.error = f"could not start {command[0]}: {error}"
        return result
    finally:
        for handed in ([stdin_fd] if stdin_fd is not None else []) + list(pass_fds):
            os.close(handed)
    with _live_lock:
        _live.add((process, uid))
    kept = bytearray()
    deadline = start + limits.wall_seconds
    watching = bool(watch or uid is not None)
    selector = selectors.DefaultSelector()
    selector.register(process.stdout, selectors.EVENT_READ)
    descriptor = process.stdout.fileno()
    try:
        open_pipe = True
        while open_pipe:
            # Memory and disk first: a run over either limit when its time runs out is told so.
            if watch and _disk_used(watch) + (_shared_used(uid) if shared else 0) > limits.disk_bytes:
                result.disk_full = True
                break
            if uid is not None and limits.address_space_limit and _memory_of(uid) > limits.memory_bytes:
                result.memory_full = True
                break
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                result.timed_out = process.poll() is None
                break
            for _ in selector.select(timeout=min(remaining, 0.1 if watching else 0.5)):
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
        if result.timed_out or result.flooded or result.disk_full or result.memory_full:
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
        with _live_lock:
            _live.discard((process, uid))
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


def stop_all():
    """Kills every command still running (an interrupted batch): their results are not used."""
    with _live_lock:
        live = list(_live)
    for process, uid in live:
        _kill_group(process, quiet=True)
        if uid is not None:
            _kill_uid(uid, None)


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


def _kill_uid(uid, gid, seconds=5.0):
    """Kills every process running as `uid` until none is left alive. A child that takes
    the uid calls kill(-1, SIGKILL): the kernel signals every process of the uid in one pass
    that a fork cannot slip through (a child being forked while its parent is killed is
    never created), so processes that hop to new pids (setsid, clone) cannot outrun it the
    way they outrun a listing of /proc. Repeated until none is left alive (zombies, dead
    and waiting for a parent outside the uid, do not count)."""
    deadline = time.monotonic() + seconds
    group = gid if gid is not None else uid
    # The first pass is unconditional: a process hopping to new pids may never show in a
    # listing of /proc at all.
    while True:
        if SETPRIV and KILL:
            # kill(1) of procps and of util-linux alike: "-KILL -1" is kill(-1, SIGKILL).
            subprocess.run([SETPRIV, f"--reuid={uid}", f"--regid={group}", "--clear-groups", "--", KILL, "-KILL", "-1"],
                           stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                           env={"PATH": SAFE_PATH, "LANG": "C"})
        else:
            _kill_all_as(uid, group)
        if not _alive_of(uid) or time.monotonic() >= deadline:
            return
        time.sleep(0.002)  # SIGKILL is sent; the processes take a moment to be gone


def _kill_all_as(uid, group):
    """kill(-1, SIGKILL) as `uid`, in a forked child that makes system calls only, then
    leaves without any cleanup (where there is no setpriv)."""
    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            os.setgroups([])
            os.setresgid(group, group, group)
            os.setresuid(uid, uid, uid)
            os.kill(-1, signal.SIGKILL)
            code = 0
        except ProcessLookupError:
            code = 0
        except BaseException:
            code = 2
        os._exit(code)
    os.waitpid(pid, 0)


def _alive_of(uid):
    """Pids of the processes of `uid` that are not zombies."""
    alive = []
    for pid in _pids_of(uid):
        try:
            with open(f"/proc/{pid}/stat", "rb") as file:
                state = file.read().rsplit(b")", 1)[1].split()[0]
        except (OSError, IndexError):
            continue
        if state not in (b"Z", b"X"):
            alive.append(pid)
    return alive


def _memory_of(uid):
    """Bytes that all the processes of `uid` hold together: resident and swapped out (on a
    machine with swap, memory held and left untouched would otherwise drop out of sight)."""
    kib = 0
    for pid in _pids_of(uid):
        try:
            with open(f"/proc/{pid}/status", "rb") as file:
                for line in file:
                    if line.startswith((b"VmRSS:", b"VmSwap:")):
                        kib += int(line.split()[1])
        except (OSError, IndexError, ValueError):
            continue
    return kib << 10


def _left_behind(uid):
    """Paths `uid` owns in the shared writable folders (and one level into the sticky
    folders there that others may write to, such as /tmp/.X11-unix)."""
    found = []
    for folder in SHARED_WRITABLE:
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue
        for entry in entries:
            try:
                info = entry.stat(follow_symlinks=False)
                if info.st_uid == uid:
                    found.append(entry.path)
                elif entry.is_dir(follow_symlinks=False) and info.st_mode & 0o1002 == 0o1002:
                    found += [inner.path for inner in os.scandir(entry.path)
                              if inner.stat(follow_symlinks=False).st_uid == uid]
            except OSError:
                continue
    return found


def _shared_used(uid):
    return sum(_disk_used(path) + _size(path) for path in _left_behind(uid))


def _size(path):
    try:
        return os.lstat(path).st_blocks * 512
    except OSError:
        return 0


def _remove_left_behind(uid):
    """Removes what `uid` left in the shared folders, and its System V IPC objects, so that
    nothing carries over to a later run."""
    for path in _left_behind(uid):
        if os.path.isdir(path) and not os.path.islink(path):
            shutil.rmtree(path, ignore_errors=True)
        else:
            try:
                os.unlink(path)
            except OSError:
                pass
    for kind, flag, uid_column in (("shm", "-m", 7), ("msg", "-q", 7), ("sem", "-s", 4)):
        try:
            with open(f"/proc/sysvipc/{kind}") as file:
                rows = [line.split() for line in file.readlines()[1:]]
        except OSError:
            continue
        for row in rows:
            if len(row) > uid_column and row[uid_column] == str(uid):
                subprocess.run(["ipcrm", flag, row[1]], capture_output=True, timeout=10)


def _take_back(folder, gid):
    """After a run: `folder` and what the run wrote there belong to the grader again,
    readable by the submission's group (the next command of the same submission reads the
    object the compiler wrote). A link is never followed, and a file with other hard links
    (which the run did not write) is removed rather than opened to the group."""
    me = os.getuid()

    def fix(path, is_dir):
        try:
            info = os.lstat(path)
            if not is_dir and info.st_nlink > 1:
                os.unlink(path)
                return
            os.lchown(path, me, gid)
            if not os.path.islink(path):
                os.chmod(path, 0o750 if is_dir or info.st_mode & 0o100 else 0o640)
        except OSError:
            pass

    for root, dirs, files in os.walk(folder):
        for name in dirs:
            fix(os.path.join(root, name), True)
        for name in files:
            fix(os.path.join(root, name), False)
    fix(folder, True)


def _probe(sandbox):
    result = sandbox.run(["/bin/sh", "-c", "echo ok"], limits=Limits(wall_seconds=10))
    return result.ok and result.output.strip() == b"ok"


def _bwrap_version(bwrap):
    try:
        text = subprocess.run([bwrap, "--version"], capture_output=True, text=True, timeout=10).stdout
        return tuple(int(part) for part in text.split()[-1].split(".")[:2])
    except (OSError, ValueError, IndexError, subprocess.TimeoutExpired):
        return (0, 0)


def detect(allow_bwrap=True):
    """The strongest isolation that works on this machine, checked by running a command."""
    root = os.getuid() == 0
    bwrap = shutil.which("bwrap")
    if allow_bwrap and bwrap:
        for fresh in ([True, False] if root else [False]):
            sized = _bwrap_version(bwrap) >= (0, 8)
            sandbox = Sandbox("bwrap", fresh, bwrap=bwrap, _system_binds=_system_binds(), sized_tmp=sized)
            if _probe(sandbox):
                if not sized:
                    sandbox.warning = ("bubblewrap is older than 0.8, so the sandbox's /tmp and /dev/shm (memory) "
                                       "cannot be sized: student code can fill the machine's memory there.")
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
