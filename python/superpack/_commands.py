"""One function per command of `superpack` (README, "The command line"), with the command's
options as keyword arguments. Each runs the command in this process, with the GIL released,
and returns its JSON document as a typed result; the numbers are the command's own."""
import json
import os
import subprocess

from . import _superpack
from ._document import Record
from ._errors import BY_EXIT_CODE, InputError, InternalError
from ._exact import exact_text, whole_number


class Density(Record):
    """superpack density: a family's certified lattice at p; phi is a packing density only
    where packing.verdict is "admissible"."""
    _summary = ("family", "p", "status", "phi", "packing")


class LatticeCheck(Record):
    """superpack check-lattice: whether a lattice packs the superball, with a witness if not."""
    _summary = ("p", "verdict", "phi", "contacts", "witness")


class Audit(Record):
    """superpack audit: a family's claims over a range of p, piece by piece."""
    _summary = ("audits", "undecided_pieces")


class Crossover(Record):
    """superpack crossover: a crossover point of two families, certified unique."""
    _summary = ("kind", "p", "phi")


class Slopes(Record):
    """superpack slopes: the slopes of the density curves at p = 1."""
    _summary = ("a_minus", "a_minus_family", "a_plus", "a_plus_family")


class Superdisk(Record):
    """superpack superdisk: the densest lattice packing of a superdisk (p >= 1/2), or a
    certified plane lattice below 1/2."""
    _summary = ("p", "status", "optimal_phi", "optimal_lattice")


class Best(Record):
    """superpack best: the densest certified lattice packing found at p."""
    _summary = ("p", "status", "family", "phi")


class Critical(Record):
    """superpack critical: a certified upper bound on the lattice packing density at p."""
    _summary = ("p", "status", "lower", "upper")


class Simulation(Record):
    """superpack simulate: the adaptive shrinking cell's final packing, certified."""
    _summary = ("p", "particles", "certified", "phi", "ratio_to_best_lattice")


class MolecularDynamics(Record):
    """superpack md: the event-driven molecular dynamics' jammed packing, certified."""
    _summary = ("p", "particles", "certified", "phi", "ratio_to_best_lattice")


class Report(Record):
    """superpack report: the paper's claims checked at chosen p."""
    _summary = ("rows", "undecided_cells")


class Verification(Record):
    """superpack verify: the independent checker's verdict and the claim it rendered itself."""
    _summary = ("verdict", "claim_kind", "claim")


def _run(arguments, progress, result_type, positionals=()):
    """Runs the command; `positionals` follow "--", so that a value such as '--help' is never
    read as an option."""
    if progress is not None and not callable(progress):
        raise InputError("progress: expected a callable taking one line (str), or None")
    words = arguments + ["--json"] + (["--", *positionals] if positionals else [])
    code, out, message = _superpack.run(words, progress)
    result = result_type(json.loads(out)) if out.strip() else None
    if code == 0 and result is not None:
        return result
    if code == 0:
        raise InternalError(f"superpack {arguments[0]} printed no document")
    raise BY_EXIT_CODE.get(code, InternalError)(message, result)


def _word(name, text):
    """`text` as one word of a command line: a NUL would end it early (argv is C strings), and
    the commands read UTF-8 only."""
    if "\0" in text:
        raise InputError(f"{name}: contains a NUL character, which would cut the value short")
    try:
        text.encode("utf-8")
    except UnicodeEncodeError as error:
        raise InputError(f"{name}: not valid Unicode ({text[error.start]!r} at {error.start} is a lone surrogate)") from None
    return text


def _keyword(flag):
    """The keyword argument of a command's option: --max-boxes is max_boxes."""
    return flag.lstrip("-").replace("-", "_")


def _option(arguments, flag, value, convert):
    """Appends `flag=value` unless value is None (the command's default): one word, so that a
    value starting with '-' is read as the value, never as an option."""
    if value is not None:
        arguments.append(f"{flag}={_word(_keyword(flag), convert(value))}")


def _flag(arguments, flag, value):
    if not isinstance(value, bool):
        raise InputError(f"{flag}: expected a bool, got {type(value).__name__}")
    if value:
        arguments.append(flag)


def _number(name):
    return lambda value: exact_text(value, name)


def _whole(name):
    return lambda value: whole_number(value, name)


def _text(name):
    def convert(value):
        if not isinstance(value, str):
            raise InputError(f"{name}: expected a str, got {type(value).__name__}")
        return value
    return convert


def _path(name):
    def convert(value):
        if not isinstance(value, (str, os.PathLike)):
            raise InputError(f"{name}: expected a path (str or os.PathLike), got {type(value).__name__}")
        return os.fsdecode(value)
    return convert


def _joined(name, separator, convert):
    """A str as typed, or a sequence of values joined by `separator` (a:b ranges, a,b lists)."""
    def join(value):
        if isinstance(value, str):
            return value
        try:
            parts = list(value)
        except TypeError:
            raise InputError(f"{name}: expected a str or a sequence, got {type(value).__name__}") from None
        texts = [convert(part) for part in parts]
        for text in texts:
            if separator in text:
                raise InputError(f"{name}: {text[:40]!r} holds the separator {separator!r}; give one value per element")
        return separator.join(texts)
    return join


# 'a,b,c; d,e,f; g,h,i' as typed, or three rows of three exact numbers.
_basis = _joined("basis", ";", _joined("basis row", ",", _number("basis entry")))


def _files(arguments, flag, paths):
    """--merge and --cover take several files: a word --merge=FILE each, which the command
    gathers (a name such as '-x.json' is a file then, not an option)."""
    if paths is None:
        return
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    try:
        paths = list(paths)
    except TypeError:
        raise InputError(f"{_keyword(flag)}: expected a path or a sequence of paths, got {type(paths).__name__}") from None
    if not paths:
        raise InputError(f"{_keyword(flag)}: expected at least one file")
    for path in paths:
        _option(arguments, flag, path, _path(_keyword(flag)))


def _with_p(arguments, p, family=None):
    _option(arguments, "--family", family, _text("family"))
    _option(arguments, "--p", p, _number("p"))


def density(family, p, *, digits=None, certificate=None, progress=None):
    """The family's certified lattice at p (C0, C1, O0, O1, D14, S6, minkowski-insertion)."""
    arguments = ["density"]
    _with_p(arguments, p, family)
    _option(arguments, "--digits", digits, _whole("digits"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    return _run(arguments, progress, Density)


def check_lattice(p, basis=None, family=None, *, digits=None, certificate=None, progress=None):
    """Whether the lattice (`basis` rows, or a family's certified lattice) packs the superball."""
    arguments = ["check-lattice"]
    _with_p(arguments, p, family)
    _option(arguments, "--basis", basis, _basis)
    _option(arguments, "--digits", digits, _whole("digits"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    return _run(arguments, progress, LatticeCheck)


def audit(family=None, p_range=None, *, second_root=False, pieces=None, depth=None, output_directory=None,
          certificate=None, progress=None):
    """The family's published claims checked over p_range ('a:b' or (a, b); default: the claimed range)."""
    arguments = ["audit"]
    _option(arguments, "--family", family, _text("family"))
    _option(arguments, "--p-range", p_range, _joined("p_range", ":", _number("p_range")))
    _flag(arguments, "--second-root", second_root)
    _option(arguments, "--pieces", pieces, _whole("pieces"))
    _option(arguments, "--depth", depth, _whole("depth"))
    _option(arguments, "--output-directory", output_directory, _path("output_directory"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    return _run(arguments, progress, Audit)


def crossover(kind, *, digits=None, certificate=None, progress=None):
    """A crossover of two families' densities (superpack crossover --help lists the kinds)."""
    arguments = ["crossover"]
    _option(arguments, "--digits", digits, _whole("digits"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    return _run(arguments, progress, Crossover, [_word("kind", _text("kind")(kind))])


def slopes(*, digits=None, certificate=None, progress=None):
    """The slopes of the families' density curves at p = 1."""
    arguments = ["slopes"]
    _option(arguments, "--digits", digits, _whole("digits"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    return _run(arguments, progress, Slopes)


def superdisk(p, *, digits=None, certificate=None, progress=None):
    """The densest lattice packing of the superdisk at p (a certified plane lattice below 1/2).
    The command's --scan prints CSV only: from Python, a scan is a loop over p."""
    arguments = ["superdisk"]
    _option(arguments, "--p", p, _number("p"))
    _option(arguments, "--digits", digits, _whole("digits"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    return _run(arguments, progress, Superdisk)


def best(p, *, digits=None, certificate=None, seed=None, starts=None, progress=None):
    """The densest certified lattice packing found at p. The command's --scan prints CSV or a
    plot only: from Python, a scan is a loop over p (docs/python.md draws Fig. 4 so)."""
    arguments = ["best"]
    _option(arguments, "--p", p, _number("p"))
    _option(arguments, "--digits", digits, _whole("digits"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    _option(arguments, "--seed", seed, _whole("seed"))
    _option(arguments, "--starts", starts, _whole("starts"))
    return _run(arguments, progress, Best)


def critical(p=None, *, gap=None, threads=None, shard=None, split=None, max_boxes=None, merge=None, cover=None,
             around=None, certificate=None, progress=None):
    """A certified upper bound on the lattice packing density at p (see superpack critical --help)."""
    arguments = ["critical"]
    _option(arguments, "--p", p, _number("p"))
    _option(arguments, "--gap", gap, _number("gap"))
    _option(arguments, "--threads", threads, _whole("threads"))
    _option(arguments, "--shard", shard, _text("shard"))
    _option(arguments, "--split", split, _whole("split"))
    _option(arguments, "--max-boxes", max_boxes, _whole("max_boxes"))
    _files(arguments, "--merge", merge)
    _files(arguments, "--cover", cover)
    _option(arguments, "--around", around, _number("around"))
    _option(arguments, "--certificate", certificate, _path("certificate"))
    return _run(arguments, progress, Critical)


def _packing_files(arguments, xyz, mesh, png, certificate):
    _option(arguments, "--xyz", xyz, _path("xyz"))
    _option(arguments, "--mesh", mesh, _path("mesh"))
    _option(arguments, "--png", png, _path("png"))
    _option(arguments, "--certificate", certificate, _path("certificate"))


def simulate(p, n, *, steps=None, seed=None, init=None, pressure=None, xyz=None, mesh=None, png=None,
             certificate=None, progress=None):
    """N superballs by the adaptive shrinking cell; the final packing certified."""
    arguments = ["simulate"]
    _option(arguments, "--p", p, _number("p"))
    _option(arguments, "--n", n, _whole("n"))
    _option(arguments, "--steps", steps, _whole("steps"))
    _option(arguments, "--seed", seed, _whole("seed"))
    _option(arguments, "--init", init, _text("init"))
    _option(arguments, "--pressure", pressure, _number("pressure"))
    _packing_files(arguments, xyz, mesh, png, certificate)
    return _run(arguments, progress, Simulation)


def md(p, n, growth, *, seed=None, init=None, cell=None, max_collisions=None, pressure_limit=None, xyz=None,
       mesh=None, png=None, certificate=None, progress=None):
    """N growing superballs by event-driven molecular dynamics until jammed; the packing certified."""
    arguments = ["md"]
    _option(arguments, "--p", p, _number("p"))
    _option(arguments, "--n", n, _whole("n"))
    _option(arguments, "--growth", growth, _number("growth"))
    _option(arguments, "--seed", seed, _whole("seed"))
    _option(arguments, "--init", init, _text("init"))
    _option(arguments, "--cell", cell, _text("cell"))
    _option(arguments, "--max-collisions", max_collisions, _whole("max_collisions"))
    _option(arguments, "--pressure-limit", pressure_limit, _number("pressure_limit"))
    _packing_files(arguments, xyz, mesh, png, certificate)
    return _run(arguments, progress, MolecularDynamics)


def report(*, digits=None, p_values=None, output=None, progress=None):
    """The paper's claims checked at chosen p values ('a,b,c' or a sequence)."""
    arguments = ["report"]
    _option(arguments, "--digits", digits, _whole("digits"))
    _option(arguments, "--p-values", p_values, _joined("p_values", ",", _number("p_values")))
    _option(arguments, "--output", output, _path("output"))
    return _run(arguments, progress, Report)


def verify(path, *, threads=None):
    """The certificate replayed by the independent checker, superpack-verify, in its own process
    (it shares no code with the rest). Raises InvalidCertificate when it rejects the file."""
    checker = os.path.join(os.path.dirname(__file__), "superpack-verify")
    # superpack-verify reads `--threads N` as two words.
    arguments = [checker, "--json"] + ([] if threads is None else ["--threads", whole_number(threads, "threads")])
    arguments += ["--", _word("path", _path("path")(path))]
    finished = subprocess.run(arguments, capture_output=True, text=True, check=False)
    result = Verification(json.loads(finished.stdout)) if finished.stdout.strip() else None
    if finished.returncode == 0 and result is not None:
        return result
    message = finished.stderr.strip().splitlines()[-1] if finished.stderr.strip() else f"superpack-verify exited {finished.returncode}"
    raise BY_EXIT_CODE.get(finished.returncode, InternalError)(message, result)
