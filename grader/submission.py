"""Finds a student's chapter files in a submission: a folder, a .zip or a .tar.gz.

Only the chapter file names (chapters/CHAPTERS ids, '-' as '_', plus .cpp) are ever taken;
every other file is ignored. Archives are read member by member and never extracted, so a
path like ../../x or a symlink in an archive cannot write or read outside the grader's folder."""
import contextlib
import gzip
import io
import os
import pathlib
import tarfile
import time
import zipfile

MAX_SOURCE_BYTES = 1 << 20   # a chapter file larger than this is not a hand-written solution
# Reading a tar archive decompresses it whole; a gzip bomb must be refused within seconds.
MAX_ARCHIVE_BYTES = 64 << 20
MAX_ARCHIVE_SECONDS = 10.0
MAX_MEMBERS = 10_000
SUFFIXES = (".tar.gz", ".tgz", ".zip", ".tar")


class SubmissionError(Exception):
    """The submission cannot be read at all (not a folder, corrupt archive...)."""


def display_name(path):
    name = pathlib.Path(path).name
    for suffix in SUFFIXES:
        if name.lower().endswith(suffix):
            return name[: -len(suffix)] or name
    return name


def chapter_files(path, wanted):
    """{file name: (bytes, where found)} for the names in `wanted` that the submission holds.

    A file at the top wins; otherwise the shallowest copy anywhere (students often hand in
    their whole skeleton/ folder). Returns notes about ambiguous or oversized files too."""
    path = pathlib.Path(path)
    if path.is_dir():
        return _select(_folder_members(path), wanted)
    if path.is_file():
        # The members read lazily from the open archive, so it stays open while choosing.
        with _open_archive(path) as members:
            return _select(members, wanted)
    raise SubmissionError(f"{path} does not exist")


def _select(members, wanted):
    found, notes = {}, []
    for name in wanted:
        candidates = sorted((m for m in members if m[0].rsplit("/", 1)[-1] == name and "__MACOSX" not in m[0]),
                            key=lambda m: (m[0].count("/"), m[0]))
        if not candidates:
            continue
        where, size, read = candidates[0]
        if len(candidates) > 1 and candidates[1][0].count("/") == where.count("/"):
            notes.append(f"several copies of {name}; graded {where}")
        if size > MAX_SOURCE_BYTES:
            notes.append(f"{where} is larger than {MAX_SOURCE_BYTES // 1024} KiB; graded as the untouched skeleton")
            continue
        try:
            found[name] = (read(), where)
        except Exception as error:
            raise SubmissionError(f"cannot read {where}: {error}") from None
    return found, notes


def _folder_members(root):
    members = []
    for folder, dirs, files in os.walk(root, followlinks=False):
        dirs[:] = [d for d in dirs if not os.path.islink(os.path.join(folder, d))]
        for file in files:
            full = os.path.join(folder, file)
            if os.path.islink(full) or not os.path.isfile(full):
                continue  # a link could point at the instructor's files
            rel = os.path.relpath(full, root).replace(os.sep, "/")
            members.append((rel, os.path.getsize(full), lambda full=full: _read_capped(full)))
    return members


def _read_capped(path):
    with open(path, "rb") as file:
        return file.read(MAX_SOURCE_BYTES + 1)


@contextlib.contextmanager
def _open_archive(path):
    lower = path.name.lower()
    try:
        if zipfile.is_zipfile(path):
            archive = zipfile.ZipFile(path)
            members = [(info.filename.strip("/"), info.file_size, lambda info=info: archive.read(info))
                       for info in archive.infolist() if not info.is_dir()]
        elif lower.endswith((".tar.gz", ".tgz", ".tar")) or tarfile.is_tarfile(path):
            archive, members = _read_tar(path)
        else:
            archive = None
    except (OSError, zipfile.BadZipFile, tarfile.TarError, EOFError) as error:
        raise SubmissionError(f"cannot open the archive {path.name}: {error}") from None
    if archive is not None and len(members) > MAX_MEMBERS:
        if hasattr(archive, "close"):
            archive.close()
        raise SubmissionError(f"the archive {path.name} holds more than {MAX_MEMBERS} files: refused")
    if archive is None:
        raise SubmissionError(f"{path.name} is neither a folder nor a .zip or .tar.gz archive")
    with archive:
        yield members


class _Bounded(io.RawIOBase):
    """A read-only stream that stops with a SubmissionError once more than MAX_ARCHIVE_BYTES
    came out of it or MAX_ARCHIVE_SECONDS went by, whatever the archive's headers claim."""

    def __init__(self, stream, name):
        self.stream, self.name, self.count = stream, name, 0
        self.deadline = time.monotonic() + MAX_ARCHIVE_SECONDS

    def readable(self):
        return True

    def readinto(self, buffer):
        if self.count > MAX_ARCHIVE_BYTES:
            raise SubmissionError(f"the archive {self.name} expands to more than {MAX_ARCHIVE_BYTES >> 20} MiB: "
                                  "refused (hand in only your source files)")
        if time.monotonic() > self.deadline:
            raise SubmissionError(f"reading the archive {self.name} took longer than {MAX_ARCHIVE_SECONDS:g} s: refused")
        data = self.stream.read(min(len(buffer), 1 << 16))
        buffer[:len(data)] = data
        self.count += len(data)
        return len(data)


def _read_tar(path):
    """Every regular file of a tar or tar.gz, each read in full once (they are small: the
    whole archive is bounded), so nothing is decompressed twice."""
    with open(path, "rb") as raw:
        compressed = raw.read(2) == b"\x1f\x8b"
    source = gzip.open(path, "rb") if compressed else open(path, "rb")
    bounded = io.BufferedReader(_Bounded(source, path.name))
    members = []
    try:
        with tarfile.open(fileobj=bounded, mode="r|") as archive:
            for info in archive:
                if not info.isfile():
                    continue
                data = archive.extractfile(info).read(MAX_SOURCE_BYTES + 1)
                name = info.name.strip("/")
                members.append((name[2:] if name.startswith("./") else name, info.size, lambda data=data: data))
                if len(members) > MAX_MEMBERS:
                    break
    finally:
        source.close()
    return contextlib.nullcontext(), members
