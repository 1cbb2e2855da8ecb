"""Collects docs/validation/*/summary.json into docs/validation/README.md: one table of every
validation study with its figures, targets and references (run by `make validate`)."""
import json
import os
import sys

root = sys.argv[1] if len(sys.argv) > 1 else "docs/validation"
lines = ["# Validation studies", "",
         "Regenerate with `make validate` (or `build/curvsph validate NAME`). Each study's own "
         "folder holds its summary CSV data, plots and a README with the details; the "
         "per-particle dumps of its runs (profiles, point sets, snapshots) are written there "
         "by `validate` and ignored by git (.gitignore).", "",
         "| study | figure | measured | target | reference | |", "|---|---|---|---|---|---|"]
for name in sorted(os.listdir(root)):
    path = os.path.join(root, name, "summary.json")
    if not os.path.isfile(path):
        continue
    for row in json.load(open(path)):
        value = row["value"]
        # A figure without a target (reported for comparison) is neither a pass nor a miss.
        status = ("reported" if row["target"].startswith("reported") else "pass") \
            if row["pass"] else "**miss**"
        shown = "n/a" if value is None else f"{value:.4g}"  # NaN is written as null
        lines.append(f"| [{name}]({name}/README.md) | `{row['figure']}` | {shown} | "
                     f"{row['target']} | {row['reference']} | "
                     f"{status} |")
open(os.path.join(root, "README.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
