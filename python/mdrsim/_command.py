"""The console script `mdrsim`: runs the mdrsim command that the package carries in bin/."""

import os
import sys
from pathlib import Path

COMMAND = Path(__file__).resolve().parent / "bin" / "mdrsim"


def main():
    """Replaces this process by the command with the same arguments, so that its output, exit
    code and signal handling are the command's own."""
    if not os.access(COMMAND, os.X_OK):
        sys.stderr.write(f"mdrsim: the command is missing from this installation ({COMMAND}); "
                         "reinstall the package\n")
        return 1
    sys.stdout.flush()
    sys.stderr.flush()
    os.execv(COMMAND, ["mdrsim", *sys.argv[1:]])
    return 1  # not reached: execv returns only by raising


if __name__ == "__main__":
    sys.exit(main())
