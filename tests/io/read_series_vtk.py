"""Reads a curvsph series with VTK's own Python module (Debian python3-vtk9), as ParaView
would: the DataSet entries of series.pvd (time, part, name, file) and each file through
vtkXMLGenericDataObjectReader. Prints one JSON object: per entry its time, part, name, file,
number of points, verts, lines and polys, and {array name: [tuples, components, sum of all values as VTK decoded
them, the same sum as scripts/vtp.py decodes them (.vtp files only, else null)]}. Exit 4
when VTK cannot be imported (the test skips then), 1 on a read error."""
import json
import os
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
except ImportError as e:
    print(f"cannot import vtk: {e}", file=sys.stderr)
    sys.exit(4)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
from vtp import read_vtp  # noqa: E402

pvd = sys.argv[1]
root = os.path.dirname(os.path.abspath(pvd))
entries = []
for ds in ET.parse(pvd).getroot().iter("DataSet"):
    path = os.path.join(root, ds.get("file"))
    reader = vtkXMLGenericDataObjectReader()
    reader.SetFileName(path)
    reader.Update()
    out = reader.GetOutput()
    if out is None or reader.GetErrorCode() != 0:
        print(f"VTK could not read {path}", file=sys.stderr)
        sys.exit(1)
    ours = read_vtp(path) if path.endswith(".vtp") else {}

    def ours_sum(name):
        a = ours.get("points" if name == "Points" else name)
        return None if a is None else float(a.astype("float64").sum())

    arrays = {}
    pd = out.GetPointData()
    for k in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(k)
        arrays[a.GetName()] = [a.GetNumberOfTuples(), a.GetNumberOfComponents(),
                               float(vtk_to_numpy(a).astype("float64").sum()),
                               ours_sum(a.GetName())]
    pts = out.GetPoints()
    arrays["Points"] = [pts.GetNumberOfPoints(), 3,
                        float(vtk_to_numpy(pts.GetData()).astype("float64").sum()),
                        ours_sum("Points")]
    entries.append({"time": float(ds.get("timestep")), "part": int(ds.get("part")),
                    "name": ds.get("name", ""), "file": ds.get("file"),
                    "points": out.GetNumberOfPoints(), "verts": out.GetNumberOfVerts(),
                    "lines": out.GetNumberOfLines(), "polys": out.GetNumberOfPolys(),
                    "arrays": arrays})
print(json.dumps(entries))
