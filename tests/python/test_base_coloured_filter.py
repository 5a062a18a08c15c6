"""The base colour inputs of the lighting filters live on one wrapped base
class, slBaseColouredFilter: slRadianceFilter and slRadianceReference derive
from it, the filters without a base colour (slCosineField, slLobesOnMesh) do
not, and each filter prints the three inputs once, with the values set."""
import unittest

import shadelab
import vtk

COLOURED = (shadelab.slRadianceFilter, shadelab.slRadianceReference)
UNCOLOURED = (shadelab.slCosineField, shadelab.slLobesOnMesh)
NAMES = ("DiffuseColorArrayName", "DiffuseTexture", "DiffuseTextureFileName")


class BaseColouredFilterTest(unittest.TestCase):
    def test_base_class_is_wrapped_abstract_and_shared(self):
        base = shadelab.slBaseColouredFilter
        self.assertTrue(issubclass(base, shadelab.slLitFilter))
        with self.assertRaises(TypeError):
            base()
        for make in COLOURED:
            self.assertIsInstance(make(), base, make.__name__)
        for make in UNCOLOURED:
            obj = make()
            self.assertNotIsInstance(obj, base, make.__name__)
            self.assertFalse(hasattr(obj, "SetDiffuseColorArrayName"), make.__name__)

    def test_print_lists_each_input_once_with_its_value(self):
        image = vtk.vtkImageData()
        for make in COLOURED:
            f = make()
            f.SetDiffuseColorArrayName("Colours")
            f.SetDiffuseTexture(image)
            f.SetDiffuseTextureFileName("base.png")
            lines = [line.strip() for line in str(f).splitlines()]
            for name in NAMES:
                found = [line for line in lines if line.startswith(name + ":")]
                self.assertEqual(len(found), 1, (make.__name__, name, found))
            self.assertIn("DiffuseColorArrayName: Colours", lines)
            self.assertIn("DiffuseTextureFileName: base.png", lines)
            self.assertNotIn("DiffuseTexture: 0", lines)

    def test_texture_change_modifies_each_filter(self):
        """A filter re-executes when its texture changes (GetMTime())."""
        for make in COLOURED:
            f = make()
            image = vtk.vtkImageData()
            f.SetDiffuseTexture(image)
            before = f.GetMTime()
            image.Modified()
            self.assertGreater(f.GetMTime(), before, make.__name__)


if __name__ == "__main__":
    unittest.main()
