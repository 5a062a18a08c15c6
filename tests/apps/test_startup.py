"""What the `shadelab` program loads when it starts: not OpenImageIO (261
shared libraries, most of the start-up time), which the image reader and
writer open on first use from libShadeLabImageCodec.so. The time itself is
measured by hand (docs/architecture.md), not asserted here."""
import os
import subprocess
import unittest

SHADELAB = os.environ["SHADELAB_EXE"]


class StartupTest(unittest.TestCase):
    def test_openimageio_is_not_loaded_at_start(self):
        libraries = subprocess.run(["ldd", SHADELAB], capture_output=True, text=True, check=True).stdout
        self.assertIn("libShadeLabIO", libraries)
        self.assertNotIn("libOpenImageIO", libraries)
        self.assertNotIn("libShadeLabImageCodec", libraries)

    def test_the_codec_is_beside_the_io_library(self):
        libraries = subprocess.run(["ldd", SHADELAB], capture_output=True, text=True, check=True).stdout
        io = next(line.split("=>")[1].split("(")[0].strip() for line in libraries.splitlines()
                  if "libShadeLabIO" in line)
        codec = os.path.join(os.path.dirname(io), "libShadeLabImageCodec.so")
        self.assertTrue(os.path.exists(codec), codec)
        codec_libraries = subprocess.run(["ldd", codec], capture_output=True, text=True, check=True).stdout
        self.assertIn("libOpenImageIO", codec_libraries)


if __name__ == "__main__":
    unittest.main()
