"""Expected to fail on Debian 12: ParaView 5.11's bundled VTK cannot read XML
files in the default appended layout with Debian 12's libexpat (the
CVE-2023-52425 fix changed how expat hands over the appended data; Debian
patched its vtk9 9.1 but not ParaView). run-tests.sh counts a failure here as
expected and a pass as news: then Debian has fixed it, and VTP inputs need no
longer be inline binary.

    pvpython test_libexpat.py MESH.vtp WORK_DIR
"""
import os
import sys

from paraview import servermanager  # noqa: F401  (ParaView's VTK)
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

mesh, work = sys.argv[1:3]
reader = vtkXMLPolyDataReader()
reader.SetFileName(mesh)
reader.Update()
cells = reader.GetOutput().GetNumberOfCells()

appended = os.path.join(work, "appended.vtp")
writer = vtkXMLPolyDataWriter()
writer.SetInputData(reader.GetOutput())
writer.SetDataModeToAppended()
writer.SetFileName(appended)
writer.Write()

back = vtkXMLPolyDataReader()
back.SetFileName(appended)
back.Update()
read = back.GetOutput().GetNumberOfCells()
print("appended layout: wrote %d cells, read back %d" % (cells, read))
sys.exit(0 if read == cells and cells > 0 else 1)
