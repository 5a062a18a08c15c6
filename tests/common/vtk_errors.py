"""The Python view of a failure in ShadeLab's VTK layer.

A ShadeLab filter, reader, writer or scene fails as VTK's objects do: an
ErrorEvent with its one-line reason, an empty output, a failed update or a
false return. These helpers observe the object's ErrorEvent while it runs
(so nothing is printed) and give the reason back, "" on success.
"""
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING


def one_line(text):
    """The reason in a VTK error text, after its "ERROR: In FILE, line N"
    line and its "Class (0x...): " preamble."""
    body = text.split("\n", 1)[1] if text.startswith("ERROR: In ") else text
    _, found, reason = body.partition("): ")
    return (reason if found else body).strip().replace("\n", " ")


def call_error(obj, call):
    """Runs call() (true on success); "" or the first error's reason."""
    messages = []

    @calldata_type(VTK_STRING)
    def keep(caller, event, text):
        messages.append(text)

    tag = obj.AddObserver("ErrorEvent", keep)
    try:
        succeeded = call()
    finally:
        obj.RemoveObserver(tag)
    if succeeded:
        return ""
    return one_line(messages[0]) if messages else obj.GetClassName() + " failed"


def update_error(algorithm):
    """Updates algorithm; "" or the first error's reason."""
    return call_error(algorithm, lambda: algorithm.GetExecutive().Update())
