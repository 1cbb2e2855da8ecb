"""Reads curvsph's .vtp files (VTK XML PolyData, binary appended, UInt64 headers), raw or
compressed with vtkZLibDataCompressor (output.compress: zlib), Float64 or Float32 arrays
(output.precision)."""
import re
import zlib

import numpy as np

_TYPES = {"Float64": np.float64, "Float32": np.float32, "Int32": np.int32, "Int64": np.int64,
          "Int8": np.int8, "UInt8": np.uint8}


def _u64(raw, at, count=1):
    return [int(v) for v in np.frombuffer(raw[at:at + 8 * count], dtype="<u8")]


def _block(raw, at, compressed):
    """The bytes of one appended array starting at `at`."""
    if not compressed:
        (nbytes,) = _u64(raw, at)
        return raw[at + 8:at + 8 + nbytes]
    # [nblocks][block size][last block size, 0: full][compressed size of each block] data
    nb, _bs, _last = _u64(raw, at, 3)
    sizes = _u64(raw, at + 24, nb)
    pos = at + 24 + 8 * nb
    out = []
    for cs in sizes:
        out.append(zlib.decompress(raw[pos:pos + cs]))
        pos += cs
    return b"".join(out)


def read_vtp(path):
    """Returns {"points": (n,3) array, name: array, ...} for every PointData array."""
    raw = open(path, "rb").read()
    marker = raw.index(b'<AppendedData encoding="raw">')
    start = raw.index(b"_", marker) + 1
    header = raw[:marker].decode("utf-8", "replace")
    compressed = 'compressor="vtkZLibDataCompressor"' in header
    out = {}
    for m in re.finditer(r"<DataArray([^>]*)>", header):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        if "offset" not in attrs:
            continue
        name = attrs.get("Name", "")
        if name in ("connectivity", "offsets"):
            continue
        dtype = np.dtype(_TYPES[attrs["type"]]).newbyteorder("<")
        comps = int(attrs.get("NumberOfComponents", "1"))
        arr = np.frombuffer(_block(raw, start + int(attrs["offset"]), compressed), dtype=dtype)
        if comps > 1:
            arr = arr.reshape(-1, comps)
        out["points" if name == "Points" else name] = arr
    return out
