"""External algorithms for the analysis: the folders of plug-in manifests named on a script's command
line go into POLYDECOMP_PLUGINS, which every polydecomp and polydecomp-bench it starts reads (after the
project's peers/ and any folders the variable already names)."""

import os


def use_plugins(folders):
    """Adds `folders` (absolute) to POLYDECOMP_PLUGINS for the processes started from here on."""
    if not folders:
        return
    named = [os.path.abspath(f) for f in folders]
    existing = os.environ.get("POLYDECOMP_PLUGINS")
    os.environ["POLYDECOMP_PLUGINS"] = ":".join(([existing] if existing else []) + named)


def add_plugins_argument(parser):
    """The scripts' --plugins option: a folder of plug-in manifests, any number of times."""
    parser.add_argument("--plugins", action="append", default=[],
                        help="a folder of external algorithms' manifests (any number of times)")
