"""Runs every ```sh block of docs/manual.md, in order, in one bash in an empty folder, with the
installed curvsph first on the PATH (issue 35 item 1): what a reader copies is what runs.

A block may be preceded by an HTML comment `<!-- test: ... -->` (the manual explains it):
  skip[: reason]   the block is not run (it builds or installs the project itself);
  python=MODULE    the block runs only where `python3 -c "import MODULE"` succeeds;
  anything else    arguments inserted after every `curvsph run` of the block (`--set`
                   overrides that make the run tiny; a later --set in the block still wins).
A block without a comment runs as it is. The test fails when a block exits non-zero (the
block is named with its line in the manual and its output shown), when the manual has no
block, or when a comment is not directly above a block.

Usage: run_manual.py MANUAL.md PREFIX (PREFIX: the install made by the Install.IntoPrefix test).
"""
import os
import re
import subprocess
import sys
import tempfile

FENCE = re.compile(r"^```(\w*)\s*$")
MARK = re.compile(r"^<!--\s*test:(.*?)-->\s*$")


def blocks(path):
    """(line of the fence, language, marker text or None, body) of every fenced block."""
    out, lines = [], open(path, encoding="utf-8").read().split("\n")
    i, mark, mark_line = 0, None, None
    while i < len(lines):
        m = MARK.match(lines[i])
        if m:
            mark, mark_line = m.group(1).strip(), i + 1
            i += 1
            continue
        f = FENCE.match(lines[i])
        if f and f.group(1):
            start, body = i + 1, []
            i += 1
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            if mark is not None and mark_line != start - 1:
                raise SystemExit(f"{path}:{mark_line}: test comment not directly above a block")
            out.append((start, f.group(1), mark, "\n".join(body) + "\n"))
            mark = None
        elif mark is not None and lines[i].strip():
            raise SystemExit(f"{path}:{mark_line}: test comment not directly above a block")
        i += 1
    return out


def has_module(name, env):
    return subprocess.run(["python3", "-c", f"import {name}"], capture_output=True,
                          env=env).returncode == 0


def main():
    manual, prefix = sys.argv[1], os.path.abspath(sys.argv[2])
    curvsph = os.path.join(prefix, "bin", "curvsph")
    if not os.access(curvsph, os.X_OK):
        raise SystemExit(f"no installed curvsph at {curvsph}")
    # The manual is written for Debian: its python3 (with python3-numpy) is /usr/bin/python3,
    # ahead of any other python3 on the PATH (a pyenv shim without numpy).
    env = dict(os.environ, PREFIX=prefix,
               PATH=f"{prefix}/bin:/usr/bin:{os.environ.get('PATH', '')}")
    script, ran, skipped = [], [], []
    for line, lang, mark, body in blocks(manual):
        if lang != "sh":
            continue
        words = (mark or "").split()
        if words and words[0].startswith("skip"):
            skipped.append(f"line {line}: {mark}")
            continue
        need = [w.split("=", 1)[1] for w in words if w.startswith("python=")]
        missing = [n for n in need if not has_module(n, env)]
        if missing:
            skipped.append(f"line {line}: python module {', '.join(missing)} missing")
            continue
        extra = " ".join(w for w in words if not w.startswith("python="))
        if extra:
            body = body.replace("curvsph run ", f"curvsph run {extra} ")
        # Each block in a subshell of the one session (variables set by a block are not needed
        # later: PREFIX and PATH come from the environment), stopping at its first failure.
        script.append(f"echo '@@ block at line {line}'\n( set -euo pipefail\n{body})\n")
        ran.append(line)
    if not ran:
        raise SystemExit(f"{manual}: no sh block to run")
    with tempfile.TemporaryDirectory(prefix="curvsph_manual_") as work:
        text = "set -e\n" + "".join(script)
        r = subprocess.run(["bash", "-c", text], cwd=work, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
    print(r.stdout)
    for s in skipped:
        print(f"skipped {s}")
    if r.returncode != 0:
        last = re.findall(r"@@ block at line (\d+)", r.stdout)
        where = f"the block at line {last[-1]}" if last else "a block"
        raise SystemExit(f"FAIL: {where} of {manual} exited {r.returncode}")
    print(f"{len(ran)} blocks of {manual} ran (lines {', '.join(map(str, ran))})")


if __name__ == "__main__":
    main()
