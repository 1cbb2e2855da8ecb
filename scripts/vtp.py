"""Reads curvsph's .vtp files (VTK XML PolyData, binary appended raw, UInt64 headers)."""
import re
import numpy as np

_TYPES = {"Float64": np.float64, "Float32": np.float32, "Int32": np.int32, "Int64": np.int64,
          "Int8": np.int8, "UInt8": np.uint8}


def read_vtp(path):
    """Returns {"points": (n,3) array, name: array, ...} for every PointData array."""
    raw = open(path, "rb").read()
    marker = raw.index(b'<AppendedData encoding="raw">')
    start = raw.index(b"_", marker) + 1
    header = raw[:marker].decode("utf-8", "replace")
    out = {}
    for m in re.finditer(r"<DataArray([^>]*)>", header):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        if "offset" not in attrs:
            continue
        name = attrs.get("Name", "")
        dtype = _TYPES[attrs["type"]]
        comps = int(attrs.get("NumberOfComponents", "1"))
        off = start + int(attrs["offset"])
        nbytes = int(np.frombuffer(raw[off:off + 8], dtype=np.uint64)[0])
        arr = np.frombuffer(raw[off + 8:off + 8 + nbytes], dtype=dtype)
        if comps > 1:
            arr = arr.reshape(-1, comps)
        out["points" if name == "Points" else name] = arr
    return out
