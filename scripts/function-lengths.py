#!/usr/bin/env python3
"""Measures every function's length in src/, include/ and checker/ and holds the length rule.

The rule: no function over 100 lines, and at most 10 over 60. Functions that break it today
are listed in scripts/long-functions.txt (file, function, length); the list is a ratchet:
the check fails if a function not in the list is over 60 lines, a listed one grew, a listed
one is no longer over 60 (or is gone: take it off the list, so that it cannot grow back), or
more functions are over 60 than the list holds. It prints how many are over 100 and over 60,
and how far that is from the goal. --write-list rewrites the list from today's functions
(after a function was shortened or split).

How a length is measured: the lines from the first line of the declarator (its specifiers
or return type; a template<...> header and the comments before it are not counted) to the
line of its closing brace, both included, blank and comment lines within included. Every function
definition is measured, free or member: a member function defined inside its class's body
counts on its own (as Class::name), and a class body itself is not a function (event_md.cpp's
class Simulation is measured member by member). A lambda or a local class counts as part of
the function it is written in, not on its own. The scanner blanks comments, string and
character literals and preprocessor lines, matches braces, and calls a brace block a function
body when what precedes it is a declarator: a name, a parenthesised parameter list, then only
qualifiers (const, noexcept, override, ->, a constructor's initialisers ...). Overloads
of one name in one file are told apart by their order in the file: name, name (2), ...
Exit 0 when the rule's ratchet holds, 1 with one line per violation otherwise.
"""
import argparse
import os
import re
import sys

FOLDERS = ("src", "include", "checker")
LIMIT = 100
LONG = 60
ALLOWED_LONG = 10
LIST = os.path.join("scripts", "long-functions.txt")

SCOPE_KEYWORDS = re.compile(r"\b(namespace|class|struct|union|extern)\b")
NOT_A_FUNCTION = re.compile(r"\b(enum|if|for|while|switch|catch|do|else|return|sizeof|decltype)\b\s*$")
TRAILER_WORDS = {"const", "noexcept", "override", "final", "mutable", "volatile", "try", "&", "&&"}


def blank_code(text):
    """text with comments, string and character literals and preprocessor lines replaced by
    spaces (newlines kept, so that line numbers stay)."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":
            # A preprocessor line, with its continuations.
            while i < n and not (text[i] == "\n" and text[i - 1] != "\\"):
                out.append("\n" if text[i] == "\n" else " ")
                i += 1
            continue
        if c == "/" and text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if c == "/" and text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append("".join("\n" if ch == "\n" else " " for ch in text[i:end]))
            i = end
            continue
        raw = re.match(r'R"([^()\\ ]{0,16})\(', text[i:i + 20]) if c == "R" else None
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + raw.group(1) + '"', i)
            end = n if end < 0 else end + len(raw.group(1)) + 2
            out.append("".join("\n" if ch == "\n" else " " for ch in text[i:end]))
            i = end
            continue
        if c == "'" and i > 0 and text[i - 1].isalnum() and re.match(r"[0-9A-Fa-f]", text[i + 1:i + 2]) \
                and re.search(r"\b[0-9][0-9A-Fa-fxXbB']*$", text[max(0, i - 40):i]):
            out.append(" ")  # a digit separator (1'000), not a character literal
            i += 1
            continue
        if c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n - 1) - i - 1) + c)
            i = j + 1
            continue
        out.append(c)
        line_start = c == "\n" or (line_start and c in " \t")
        i += 1
    return "".join(out)


def matching(text, open_index, opening, closing):
    """The index of the bracket that closes the one at open_index (len(text) if none)."""
    depth = 0
    for k in range(open_index, len(text)):
        if text[k] == opening:
            depth += 1
        elif text[k] == closing:
            depth -= 1
            if depth == 0:
                return k
    return len(text)


def declared_name(head):
    """The function name if head (the text before a '{') declares a function, else None."""
    head = head.strip()
    if not head.endswith((")", "}")) and not re.search(r"[\w>&*]\s*$", head):
        return None
    operator = re.search(r"\boperator\s*(\(\s*\)|[^\s(]+)\s*\(", head)
    if operator:
        open_index = operator.end() - 1
        name = "operator" + re.sub(r"\s", "", operator.group(1))
        before = head[:operator.start()]
    else:
        # The parameter list: the first '(' at the top level that follows a name.
        depth_angle = 0
        open_index = None
        for k, ch in enumerate(head):
            if ch == "<":
                depth_angle += 1
            elif ch == ">" and depth_angle:
                depth_angle -= 1
            elif ch == "(" and depth_angle == 0:
                open_index = k
                break
        if open_index is None:
            return None
        before = head[:open_index].rstrip()
        found = re.search(r"(~?[A-Za-z_]\w*(?:\s*<[^()]*>)?(?:\s*::\s*~?[A-Za-z_]\w*(?:\s*<[^()]*>)?)*)$",
                          before)
        if not found:
            return None
        name = re.sub(r"\s", "", found.group(1))
        before = before[:found.start()]
        if NOT_A_FUNCTION.search(name) or NOT_A_FUNCTION.search(before):
            return None
    if "=" in before.replace("==", ""):
        return None
    close_index = matching(head, open_index, "(", ")")
    if close_index >= len(head):
        return None
    trailer = re.sub(r"\bnoexcept\s*\([^()]*\)", "", head[close_index + 1:])
    initialisers = re.search(r"(?<!:):(?!:)", trailer)
    if initialisers:
        # A constructor's initialisers: the body follows the last one's ) or }; a '{' after a
        # member's name opens its braced initialiser instead.
        if not trailer.rstrip().endswith((")", "}")):
            return None
        trailer = trailer[:initialisers.start()]
    trailer = re.sub(r"->.*$", "", trailer, flags=re.S)  # a trailing return type
    if all(word in TRAILER_WORDS for word in trailer.split()):
        return name
    return None


def declaration_start(code, start, end):
    """Where the declaration in code[start:end] begins after access specifiers (public:) and
    template<...> headers."""
    while True:
        access = re.match(r"\s*(public|private|protected)\s*:(?!:)", code[start:end])
        if access:
            start += access.end()
            continue
        template = re.match(r"\s*template\s*<", code[start:end])
        if not template:
            return start
        start = matching(code, start + template.end() - 1, "<", ">") + 1


def functions_in(text):
    """[(name, first line, length)] of every function defined in text (C++ source)."""
    code = blank_code(text)
    found = []
    line_of = []
    line = 1
    for ch in code:
        line_of.append(line)
        if ch == "\n":
            line += 1

    def scan(start, end, scope):
        head_start = start
        k = start
        while k < end:
            ch = code[k]
            if ch == ";":
                head_start = k + 1
            elif ch == "{":
                begin = declaration_start(code, head_start, k)
                head = code[begin:k]
                close = matching(code, k, "{", "}")
                name = declared_name(head)
                first = begin + len(head) - len(head.lstrip())
                if name is not None:
                    qualified = "::".join(scope + [name]) if scope else name
                    found.append((qualified, line_of[first], line_of[min(close, end - 1)] - line_of[first] + 1))
                    head_start = close + 1
                elif SCOPE_KEYWORDS.search(head) and "=" not in head and "(" not in head:
                    kind = re.search(r"\b(class|struct|union)\s+(?:\[\[[^\]]*\]\]\s*)?(?:alignas\([^)]*\)\s*)?"
                                     r"([A-Za-z_]\w*)", head)
                    scan(k + 1, close, scope + [kind.group(2)] if kind else scope)
                    head_start = close + 1
                # Otherwise a braced initialiser: part of the declaration that goes on.
                k = close
            elif ch == "}":
                head_start = k + 1
            k += 1

    scan(0, len(code), [])
    return found


def self_test():
    """The scanner measures what it must: braces in literals and comments, a class's inline
    members, a constructor's initialisers, a template header and a lambda."""
    text = """namespace a {
template <class T, class U = int>
int f(T t) {  // {
    const char* s = "}";
    char c = '{';
    auto g = [&](int x) {
        return x;
    };
    return g(1);
}
class Simulation {
  public:
    Simulation(int n) noexcept : n_{n}, m_(n) {
    }
    int run() const { return n_; }
  private:
    int n_, m_;
};
}  // namespace a
"""
    expected = [("f", 3, 8), ("Simulation::Simulation", 13, 2), ("Simulation::run", 15, 1)]
    found = functions_in(text)
    if found != expected:
        print(f"function-lengths self-test: expected {expected}, got {found}")
        return False
    return True


def measure(source):
    """[(file, function, first line, length)] over FOLDERS, files in sorted order."""
    rows = []
    for folder in FOLDERS:
        for directory, _, names in sorted(os.walk(os.path.join(source, folder))):
            for file_name in sorted(names):
                if not file_name.endswith((".cpp", ".hpp")):
                    continue
                path = os.path.join(directory, file_name)
                relative = os.path.relpath(path, source)
                with open(path, encoding="utf-8") as f:
                    functions = functions_in(f.read())
                seen = {}
                for name, first, length in functions:
                    seen[name] = seen.get(name, 0) + 1
                    label = name if seen[name] == 1 else f"{name} ({seen[name]})"
                    rows.append((relative, label, first, length))
    return rows


def read_list(path):
    """{(file, function): length} from the exceptions list (tab-separated; # starts a comment)."""
    listed = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line.strip() or line.startswith("#"):
                continue
            file_name, function, length = line.split("\t")
            listed[(file_name, function)] = int(length)
    return listed


def write_list(path, rows):
    long_rows = sorted((r for r in rows if r[3] > LONG), key=lambda r: (-r[3], r[0], r[1]))
    with open(path, "w", encoding="utf-8") as f:
        f.write("# Functions over 60 lines today (scripts/function-lengths.py): file, function, length,\n"
                "# tab-separated. None may grow and none may join; shorten one, then take it off\n"
                "# (scripts/function-lengths.py --write-list). The goal: none over 100, at most 10 over 60.\n")
        for file_name, function, _, length in long_rows:
            f.write(f"{file_name}\t{function}\t{length}\n")


def violations(rows, listed):
    lines = []
    current = {(r[0], r[1]): r for r in rows}
    for file_name, function, first, length in rows:
        key = (file_name, function)
        if key not in listed:
            if length > LONG:
                lines.append(f"{file_name}:{first}: {function} is {length} lines (over {LONG}, not in {LIST})")
        elif length > listed[key]:
            lines.append(f"{file_name}:{first}: {function} grew to {length} lines ({LIST} allows {listed[key]})")
    for (file_name, function), length in sorted(listed.items()):
        row = current.get((file_name, function))
        if row is None:
            lines.append(f"{LIST}: {file_name} {function} is gone: take it off the list")
        elif row[3] <= LONG:
            lines.append(f"{file_name}:{row[2]}: {function} is {row[3]} lines now: take it off {LIST}")
    over_long = sum(1 for r in rows if r[3] > LONG)
    if over_long > len(listed):
        lines.append(f"{over_long} functions are over {LONG} lines, {LIST} allows {len(listed)}")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--source", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    parser.add_argument("--write-list", action="store_true", help=f"rewrite {LIST} from today's functions")
    parser.add_argument("--all", action="store_true", help="print every function's length")
    options = parser.parse_args()
    source = os.path.abspath(options.source)
    if not self_test():
        return 1
    rows = measure(source)
    if options.all:
        for file_name, function, first, length in sorted(rows, key=lambda r: -r[3]):
            print(f"{length:5d}  {file_name}:{first}  {function}")
    list_path = os.path.join(source, LIST)
    if options.write_list:
        write_list(list_path, rows)
    found = violations(rows, read_list(list_path))
    for line in found:
        print(line)
    over_limit = sum(1 for r in rows if r[3] > LIMIT)
    over_long = sum(1 for r in rows if r[3] > LONG)
    print(f"function-lengths: {len(rows)} functions, {over_limit} over {LIMIT} lines, {over_long} over {LONG}; "
          f"the goal (none over {LIMIT}, at most {ALLOWED_LONG} over {LONG}) is {over_limit} to bring to "
          f"{LIMIT} lines or fewer and {max(0, over_long - ALLOWED_LONG)} fewer over {LONG} away")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
