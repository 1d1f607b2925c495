"""virtual_display.py: an X display of its own for `pamsim view` without a screen (Debian's
Xvfb, 1920x1080, 24-bit, no TCP), for the viewer's test and its frame-rate benchmark.

    with VirtualDisplay() as env:   # os.environ with DISPLAY set to the new server
        subprocess.run(["pamsim", "view", ...], env=env)
"""

import os
import subprocess


class VirtualDisplay:
    """Starts Xvfb on a free display number (it chooses, -displayfd) and stops it on exit."""

    def __enter__(self):
        read, write = os.pipe()
        self.xvfb = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write), "-screen", "0", "1920x1080x24", "-nolisten", "tcp"],
            pass_fds=[write],
            stderr=subprocess.DEVNULL,
        )
        os.close(write)
        with os.fdopen(read) as f:
            number = f.readline().strip()
        if not number:
            self.xvfb.kill()
            raise RuntimeError("Xvfb did not start")
        return dict(os.environ, DISPLAY=":" + number)

    def __exit__(self, *exc):
        self.xvfb.terminate()
        self.xvfb.wait()
        return False
