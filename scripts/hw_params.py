"""The table of hardware parameters (ref/model/hw_params.def) for the Python scripts: each
parameter's Verilog name and its default as that Verilog parameter's integer (bool and Metric
as 0/1). verilog_defaults(root) returns them in the table's order; a default that is not an
integer raises ValueError naming it."""
import re
from pathlib import Path

_ENTRY = re.compile(r'^RPU_HW_PARAM\(\s*\w+,\s*\w+,\s*"\w+",\s*"[-\w]+",\s*"(\w*)",\s*"[^"]*",'
                    r'\s*([^,]+),', re.M)
_NAMED = {"true": "1", "false": "0", "Metric::kAbs": "0", "Metric::kSquared": "1"}


def verilog_defaults(root):
    """{Verilog name: default} of every table entry that has a Verilog parameter."""
    text = (Path(root) / "ref/model/hw_params.def").read_text()
    out = {}
    for m in _ENTRY.finditer(text):
        name, value = m.group(1), m.group(2).strip()
        if not name:
            continue
        value = _NAMED.get(value, value)
        if not re.fullmatch(r"-?\d+", value):
            raise ValueError(f"ref/model/hw_params.def: cannot read the default of {name}: {value}")
        out[name] = int(value)
    return out
