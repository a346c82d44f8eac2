#!/usr/bin/env python3
"""Checks superpack's layering from the compiler's real include graph (g++ -MM).

The producer's layers, each a folder under include/superpack/ and src/, may include only
their own layer and the ones below it:   arith -> solve -> geometry -> problems -> cert -> render
-> cli -> python (the Python module, which runs the command lines of cli).
sim/ (floating point only) may include arith, solve and geometry, and only cli includes sim.
problems/ is one room per feature (ROOMS below): a room includes its own and earlier rooms only.
checker/ (all its rooms: core/, formulas/, claims/) includes nothing of the repository but
checker/ itself: it is the independent side.
tests/ and bench/ may include anything. Libraries: the checker uses none of the producer's
arithmetic libraries (Arb/FLINT, Boost, Eigen), and Eigen is seen only by the one file that
computes preconditioners, so no public header pulls it in; Arb/FLINT and MPFR reach a public
header only through the three entry headers of the code that calls them (arb_access.hpp,
mpfr_bounds.hpp, exact_ends.hpp), so a formula's translation unit does not read them. Every translation unit of
compile_commands.json and every header (compiled on its own, which also checks that it is
self-contained) is checked, with the system headers it reads (g++ -M).
Exit 0 when every include respects the rules, 1 with one line per violation otherwise.
"""
import argparse
import concurrent.futures
import json
import os
import shlex
import subprocess
import sys

ORDER = ["arith", "solve", "geometry", "problems", "cert", "render", "cli", "python"]
# problems/ is one room per feature, a folder in include/superpack/problems/ and src/problems/; a
# room includes its own and earlier rooms only. The floating-point guesses come first (the
# search and the families both use them), then the KKT system and local optimality (S6 is
# defined by it), the families with their audit, the features on top of them, best (which
# certifies what the search guesses among the families) and critical (measured against best).
ROOMS = ["guess", "optimality", "families", "crossover", "superdisk", "star", "periodic", "best", "critical"]
SIM_MAY_INCLUDE = {"arith", "solve", "geometry", "sim"}
SIM_USERS = {"cli"}
CHECKER_USERS = {"cert", "cli", "tests", "bench"}


def layer_of(path, source):
    """The layer a file belongs to: a producer layer, 'checker', 'tests', 'bench', 'repository'
    (elsewhere in the repository), or None outside it (system and library headers)."""
    relative = os.path.relpath(os.path.realpath(path), os.path.realpath(source))
    if relative.startswith(".."):
        return None
    parts = relative.split(os.sep)
    if parts[0] == "include" and len(parts) > 3 and parts[1] == "superpack":
        return parts[2]
    if parts[0] == "src" and len(parts) > 2:
        return parts[1]
    if parts[0] in ("checker", "tests", "bench", "python"):
        return parts[0]
    return "repository"


def room_of(path, source):
    """The room of a file of problems/ (the folder under include/superpack/problems/ or
    src/problems/), or None."""
    parts = os.path.relpath(os.path.realpath(path), os.path.realpath(source)).split(os.sep)
    if parts[:3] == ["include", "superpack", "problems"] and len(parts) > 4:
        return parts[3]
    if parts[:2] == ["src", "problems"] and len(parts) > 3:
        return parts[2]
    return None


def room_allowed(path, included_path, source):
    """May a file of problems/ include a header of problems/? Within the rooms' order only; a
    file directly in problems/ (no room) is refused, and a room's private headers (under
    src/problems/<room>/) are its own."""
    including, included = room_of(path, source), room_of(included_path, source)
    if including not in ROOMS or included not in ROOMS:
        return False
    private = os.path.relpath(os.path.realpath(included_path), os.path.realpath(source)).startswith("src" + os.sep)
    if private and included != including:
        return False
    return ROOMS.index(included) <= ROOMS.index(including)


def allowed(including, included):
    """May a file of layer `including` include a header of layer `included`?"""
    if included is None or included == including:
        return True
    if including in ("tests", "bench"):
        return True
    if included == "checker":
        return including in CHECKER_USERS
    if including == "checker":
        return False
    if included == "sim":
        return including in SIM_USERS
    if including == "sim":
        return included in SIM_MAY_INCLUDE
    if including in ORDER and included in ORDER:
        return ORDER.index(included) <= ORDER.index(including)
    return False


# Library headers by a fragment of their path, and who may read them (None: no restriction
# beyond the listed exclusions).
ENTRY_HEADERS = {"include/superpack/arith/arb_access.hpp", "include/superpack/arith/mpfr_bounds.hpp",
                 "include/superpack/arith/exact_ends.hpp"}
LIBRARIES = {
    "Eigen": {"fragment": "/eigen3/", "only": {"src/solve/approximate_inverse.cpp"}},
    "Arb/FLINT": {"fragment": "/flint/", "never": {"checker"}, "public_headers": ENTRY_HEADERS},
    "MPFR": {"fragment": "/mpfr.h", "public_headers": ENTRY_HEADERS},
    "Boost": {"fragment": "/boost/", "never": {"checker"}},
}


def library_allowed(path, layer, included_path, source):
    """May `path` (of `layer`) read the library header `included_path`?"""
    relative = os.path.relpath(os.path.realpath(path), os.path.realpath(source))
    for name, rule in LIBRARIES.items():
        if rule["fragment"] not in included_path:
            continue
        if layer in ("tests", "bench"):
            return True, name
        if layer in rule.get("never", set()):
            return False, name
        if "only" in rule and relative not in rule["only"]:
            return False, name
        if "public_headers" in rule and relative.startswith("include/") and relative not in rule["public_headers"]:
            return False, name
        return True, name
    return True, None


def violations(graph, source):
    """graph: {file: [included files]} -> one line per forbidden include."""
    lines = []
    for path, includes in sorted(graph.items()):
        including = layer_of(path, source)
        libraries_reported = set()
        for included_path in includes:
            included = layer_of(included_path, source)
            if included is None:
                permitted, library = library_allowed(path, including, included_path, source)
                if not permitted and library not in libraries_reported:
                    libraries_reported.add(library)
                    lines.append(f"{os.path.relpath(path, source)} ({including}) reads {library}: "
                                 f"{included_path}")
                continue
            if not allowed(including, included):
                lines.append(f"{os.path.relpath(path, source)} ({including}) includes "
                             f"{os.path.relpath(os.path.realpath(included_path), source)} ({included})")
            elif including == included == "problems" and not room_allowed(path, included_path, source):
                lines.append(f"{os.path.relpath(path, source)} (room {room_of(path, source)}) includes "
                             f"{os.path.relpath(os.path.realpath(included_path), source)} "
                             f"(room {room_of(included_path, source)})")
    return lines


def dependencies(arguments, directory):
    """The files a compilation reads, from g++ -M (system headers included)."""
    result = subprocess.run(arguments, cwd=directory, capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(" ".join(arguments[:3]) + "...: " + result.stderr.strip()[:2000])
    text = result.stdout.replace("\\\n", " ")
    files = text.split(":", 1)[1].split() if ":" in text else []
    return [os.path.join(directory, f) for f in files]


def dependency_command(entry):
    """The compile command of entry with -M in place of compiling (and no ccache)."""
    arguments = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
    if os.path.basename(arguments[0]) == "ccache":
        arguments = arguments[1:]
    kept, skip = [], False
    for argument in arguments:
        if skip:
            skip = False
        elif argument in ("-o", "-MF", "-MT", "-MQ"):
            skip = True
        elif argument in ("-c", "-MD", "-MMD"):
            continue
        else:
            kept.append(argument)
    source_file = entry["file"]
    return [a for a in kept if a != source_file] + ["-M"], source_file


def build_graph(source, compile_commands):
    with open(compile_commands) as f:
        entries = json.load(f)
    jobs, flags_by_layer = {}, {}
    for entry in entries:
        command, file = dependency_command(entry)
        file = os.path.join(entry["directory"], file)
        layer = layer_of(file, source)
        if layer == "repository":
            continue  # generated in the build tree (version.cpp): no layer of its own
        jobs[file] = (command + [file], entry["directory"])
        flags_by_layer.setdefault(layer, (command, entry["directory"]))
    # Headers on their own, with the flags of a translation unit of their layer.
    for top in ("include/superpack", "src", "checker"):
        for folder, _, names in os.walk(os.path.join(source, top)):
            for name in names:
                if not name.endswith(".hpp"):
                    continue
                header = os.path.join(folder, name)
                layer = layer_of(header, source)
                if layer not in flags_by_layer:
                    raise RuntimeError(f"no translation unit of layer {layer} to take flags from for {header}")
                command, directory = flags_by_layer[layer]
                jobs[header] = (command + ["-x", "c++", header], directory)
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        futures = {file: pool.submit(dependencies, *job) for file, job in jobs.items()}
        return {file: future.result() for file, future in futures.items()}


def self_test():
    """The rules reject what they must: a check that cannot fail is no check."""
    source = "/repository"
    graph = {
        "/repository/src/arith/a.cpp": ["/repository/include/superpack/problems/families/families.hpp"],
        "/repository/include/superpack/geometry/g.hpp": ["/repository/include/superpack/cert/c.hpp"],
        "/repository/checker/core/real.cpp": ["/repository/include/superpack/arith/interval.hpp"],
        "/repository/checker/claims/claim.cpp": ["/repository/src/arith/arb_support.hpp"],
        "/repository/src/problems/p.cpp": ["/repository/checker/verifier.hpp"],
        "/repository/src/cert/c.cpp": ["/repository/src/sim/s.hpp"],
        "/repository/src/sim/s.cpp": ["/repository/include/superpack/cert/c.hpp"],
        "/repository/src/render/r.cpp": ["/repository/src/cli/common.hpp", "/repository/include/superpack/sim/vector3.hpp"],
        "/repository/src/render/ok.cpp": ["/repository/include/superpack/solve/dense3.hpp",
                                          "/repository/include/superpack/cert/atomic_file.hpp"],
        "/repository/src/cli/ok.cpp": ["/repository/include/superpack/arith/interval.hpp",
                                       "/repository/checker/verifier.hpp", "/usr/include/gmp.h"],
        "/repository/checker/formulas/ok.cpp": ["/repository/checker/core/real.hpp", "/usr/include/mpfi.h"],
        "/repository/src/geometry/ok.cpp": ["/repository/include/superpack/solve/krawczyk.hpp"],
        "/repository/checker/formulas/arb.cpp": ["/usr/include/flint/arb.h"],
        "/repository/include/superpack/solve/krawczyk.hpp": ["/usr/include/eigen3/Eigen/Dense"],
        "/repository/src/solve/approximate_inverse.cpp": ["/usr/include/eigen3/Eigen/Dense"],
        "/repository/include/superpack/arith/interval.hpp": ["/usr/include/mpfr.h"],
        "/repository/include/superpack/arith/mpfr_bounds.hpp": ["/usr/include/mpfr.h"],
        "/repository/src/arith/ok.cpp": ["/usr/include/mpfr.h", "/usr/include/flint/arb.h"],
        "/repository/src/problems/guess/search.cpp": ["/repository/include/superpack/problems/best/best.hpp"],
        "/repository/src/problems/best/ok.cpp": ["/repository/include/superpack/problems/families/families.hpp",
                                                 "/repository/src/problems/best/private.hpp"],
        "/repository/src/problems/critical/c.cpp": ["/repository/src/problems/families/private.hpp"],
        "/repository/src/problems/loose.cpp": ["/repository/include/superpack/problems/guess/g.hpp"],
    }
    permitted = ("ok.cpp", "approximate_inverse.cpp", "mpfr_bounds.hpp")
    found = violations(graph, source)
    expected = 15
    if len(found) != expected or any(line.split(" ")[0].endswith(permitted) for line in found):
        print(f"check-layers self-test: expected {expected} violations, none in {permitted}, got:", *found,
              sep="\n  ")
        return False
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--source", required=True)
    parser.add_argument("--compile-commands", required=True)
    options = parser.parse_args()
    options.source = os.path.abspath(options.source)
    if not self_test():
        return 1
    try:
        graph = build_graph(options.source, options.compile_commands)
    except RuntimeError as error:
        print(f"check-layers: {error}")
        return 1
    found = violations(graph, options.source)
    for line in found:
        print(line)
    checked = sum(1 for f in graph if layer_of(f, options.source) not in ("tests", "bench"))
    print(f"check-layers: {checked} files checked, {len(found)} forbidden includes")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
