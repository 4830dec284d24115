"""docs/api.md against the mapper: every row of the mapper's setter table whose range
is "lo – hi" and whose default is a number (or on/off) states the range and default
the mapper has (which come from the one record, scatterer/IlluminationSettings.h), so
the reference page cannot drift from the code."""
import os
import re
import sys

from scatterertemplate import vtkScattererTemplateVolumeMapper

DOC = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "api.md")
ROW = re.compile(r"^\| `Set(\w+)\((int|double|bool)\)`[^|]*\| ([^|]*) \| ([^|]*) \|")

mapper = vtkScattererTemplateVolumeMapper()
failures = []
checked = 0
in_table = False  # the mapper's table: from its first row to the first line after it
for line in open(DOC, encoding="utf-8"):
    in_table = in_table or "`SetIlluminationEnabled(bool)`" in line
    if in_table and not line.startswith("|"):
        break
    m = ROW.match(line) if in_table else None
    if not m or not hasattr(mapper, "Get" + m.group(1)):
        continue
    name, kind, rng, default = m.group(1), m.group(2), m.group(3).strip(), m.group(4).strip()
    value = getattr(mapper, "Get" + name)()
    if kind == "bool":
        if default in ("on", "off"):
            checked += 1
            if bool(value) != (default == "on"):
                failures.append("%s: doc default %s, mapper %s" % (name, default, value))
        continue
    numbers = re.fullmatch(r"([-+0-9.e]+) – ([-+0-9.e]+)", rng)
    if numbers:
        checked += 1
        low, high = getattr(mapper, "Get%sMinValue" % name)(), getattr(mapper, "Get%sMaxValue" % name)()
        if (float(numbers.group(1)), float(numbers.group(2))) != (float(low), float(high)):
            failures.append("%s: doc range %s, mapper %s – %s" % (name, rng, low, high))
    if re.fullmatch(r"[-+0-9.e]+", default):
        checked += 1
        if float(default) != float(value):
            failures.append("%s: doc default %s, mapper %s" % (name, default, value))
for failure in failures:
    print("FAIL:", failure)
print("checked %d ranges and defaults in docs/api.md" % checked)
if checked < 20:
    print("FAIL: expected at least 20 (did the table's format change?)")
    sys.exit(1)
sys.exit(1 if failures else 0)
