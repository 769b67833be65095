"""python3 -m erd ...: the erd program (its main, linked into the extension), same subcommands."""
import signal
import sys

from ._erd import _cli_main


def main(argv=None):
    args = sys.argv[1:] if argv is None else list(argv)
    # Ctrl-C ends the program as it ends erd (the C code does not return to Python until done).
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    sys.stdout.flush()
    return _cli_main(["erd"] + args)


if __name__ == "__main__":
    sys.exit(main())
