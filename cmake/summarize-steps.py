"""Summary of a cmake/measure-build.sh run: the three timed phases and CPU seconds per target."""
import collections
import pathlib
import re
import sys

out = pathlib.Path(sys.argv[1])
for phase in ("configure", "shadowlab", "all"):
    user, system, wall = (float(x) for x in (out / f"{phase}.time").read_text().split()[-3:])
    print(f"{phase:10s} CPU {user + system:8.1f} s  wall {wall:8.1f} s")

per_target = collections.defaultdict(lambda: [0, 0.0])
for line in (out / "steps.tsv").read_text().splitlines():
    fields = line.split("\t")
    if len(fields) < 4:
        continue
    user, system = float(fields[0]), float(fields[1])
    match = re.search(r"CMakeFiles/([^/]+)\.dir/", fields[3])
    kind = "precompiled header" if fields[3].endswith(".gch") else "compile" if fields[3].endswith(".o") else "link"
    name = f"{match.group(1)} ({kind})" if match and kind != "compile" else match.group(1) if match else f"link {pathlib.Path(fields[3]).name}"
    per_target[name][0] += 1
    per_target[name][1] += user + system
total = sum(cpu for _, cpu in per_target.values())
print(f"steps: {sum(n for n, _ in per_target.values())}, CPU {total:.1f} s")
for name, (steps, cpu) in sorted(per_target.items(), key=lambda item: -item[1][1]):
    print(f"{cpu:8.1f} s {steps:4d}  {name}")
