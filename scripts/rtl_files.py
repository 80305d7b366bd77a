"""The RTL file list (rtl/rpu.f) for the Python scripts: the twin of scripts/rtl_files.sh.

Format (rtl/rpu.f's header): a path relative to the list's directory per line, +incdir+DIR,
// comments. read_list(path) returns (sources, incdirs), both relative to the list's directory,
in the list's order, and raises ValueError naming the entry when one does not exist.
"""
from pathlib import Path


def read_list(path):
    path = Path(path)
    base = path.parent
    sources, incdirs = [], []
    try:
        text = path.read_text()
    except OSError as e:
        raise ValueError(f"{path}: cannot read the RTL file list ({e.strerror})") from None
    for number, line in enumerate(text.splitlines(), 1):
        line = line.split("//", 1)[0].strip()
        if not line:
            continue
        if line.startswith("+incdir+"):
            d = line[len("+incdir+"):]
            if not (base / d).is_dir():
                raise ValueError(f"{path}:{number}: no directory {d}")
            incdirs.append(d)
        elif line.startswith(("+", "-")):
            raise ValueError(f"{path}:{number}: unsupported option line '{line}'")
        else:
            if not (base / line).is_file():
                raise ValueError(f"{path}:{number}: no file {line}")
            sources.append(line)
    return sources, incdirs
