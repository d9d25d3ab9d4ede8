#!/usr/bin/python3
# SPDX-License-Identifier: MIT
# Reads a .vtu file with VTK's own XML reader and prints what it saw as JSON.
#
# Usage: /usr/bin/python3 read_vtu.py FILE.vtu   (or FILE.pvtu: the parallel reader,
#        which reads the pieces the file names, beside it)
# Needs Debian's python3-vtk9, which only /usr/bin/python3 can import.
# Output: {"n_points", "n_cells", "cell_types": [...], "points": [[x, y, z], ...],
#          "cells": [[point ids in VTK order], ...],
#          "point_data" / "cell_data" / "field_data":
#              {name: {"components": k, "values": [...]}},
#          "parametric_coords": {cell type: [[r, s, t] per point in VTK order]}}
# The parametric coordinates are VTK's own (vtkCell::GetParametricCoords), so a
# test can check a writer's node order against VTK rather than against a table.
# Exits 1 (with the reason on stderr) if VTK cannot read the file.
import json
import sys

from vtkmodules.vtkCommonCore import vtkIdList, vtkObject
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader


def arrays(data):
    out = {}
    for i in range(data.GetNumberOfArrays()):
        array = data.GetArray(i)
        if array is None:  # a non-numeric array (field data may hold strings)
            continue
        k = array.GetNumberOfComponents()
        values = [array.GetComponent(t, c) for t in range(array.GetNumberOfTuples()) for c in range(k)]
        out[array.GetName()] = {"components": k, "values": values}
    return out


def main(path):
    vtkObject.GlobalWarningDisplayOff()  # errors are reported through the exit code below
    parallel = path.endswith(".pvtu")
    reader = vtkXMLPUnstructuredGridReader() if parallel else vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if reader.GetErrorCode() != 0 or grid is None or grid.GetNumberOfPoints() == 0:
        print(f"VTK could not read {path} (error code {reader.GetErrorCode()})", file=sys.stderr)
        return 1
    ids = vtkIdList()
    cells = []
    parametric = {}
    for c in range(grid.GetNumberOfCells()):
        grid.GetCellPoints(c, ids)
        n = ids.GetNumberOfIds()
        cells.append([ids.GetId(i) for i in range(n)])
        kind = grid.GetCellType(c)
        if str(kind) not in parametric:
            coords = grid.GetCell(c).GetParametricCoords()
            parametric[str(kind)] = [[coords[3 * i + j] for j in range(3)] for i in range(n)]
    json.dump({
        "n_points": grid.GetNumberOfPoints(),
        "n_cells": grid.GetNumberOfCells(),
        "cell_types": [grid.GetCellType(c) for c in range(grid.GetNumberOfCells())],
        "points": [list(grid.GetPoint(p)) for p in range(grid.GetNumberOfPoints())],
        "cells": cells,
        "point_data": arrays(grid.GetPointData()),
        "cell_data": arrays(grid.GetCellData()),
        "field_data": arrays(grid.GetFieldData()),
        "parametric_coords": parametric,
    }, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
