"""The decompositions the report draws: every key's polygon made again (`polydecomp generate` with the key's
family, n, r, holes and seed, or its corpus file) and decomposed again (`polydecomp run --json`), for the
keys small enough to read in a drawing (at most DRAW_MAX_N vertices) that ran (status ok or invalid). Every
other key gets the commands that draw it (`run --svg`) instead.

The page holds each polygon's vertices once and, per drawn key, its Steiner points and its pieces; a
generated polygon that does not come out as the key says (another n or r: its generator has changed since
the run) is not drawn, and says so. (A corpus file is its own identity: the sweep's corpus reader counts
its n after merging repeated vertices, `run` before.) Pieces are written as text, one character per
vertex index (three past len(ALPHABET)), each piece led by its size: a triangle takes four characters.
"""

import concurrent.futures
import json
import os
import shlex
import subprocess
import sys
import tempfile
from fractions import Fraction

DRAW_MAX_N = 100  # vertices (holes included) of the largest polygon drawn: more is not legible on a page
RUN_SECONDS = 10  # --max-seconds of a run made again
USAGE_ERROR = 2  # generate's exit status for options that do not go together (an r the family cannot choose)
INVALID_RESULT = 5  # run's exit status when the result is not valid; its report is printed as usual
COORDINATE_DIGITS = 7  # significant digits of a drawn coordinate
ALPHABET = "".join(chr(c) for c in range(0x21, 0x7e) if chr(c) not in "\"\\<>&'")  # safe in JSON and HTML
ESCAPE = "~"  # leads an index of two characters


def corpus_folders(context):
    """{corpus name: folder} of the run's corpora: the "dir:PATH" families of its sweep in the sweeps file
    the context names (PATH relative to that file), where that file can still be read; {} otherwise."""
    sweeps_file, sweep = context.get("sweeps_file"), context.get("sweep")
    try:
        with open(sweeps_file, encoding="utf-8") as f:
            curves = json.load(f)[sweep]["curves"]
    except (OSError, TypeError, ValueError, KeyError):
        return {}
    folders = {}
    for curve in curves:
        families = curve.get("families", [])
        for family in families if isinstance(families, list) else []:
            if isinstance(family, str) and family.startswith("dir:"):
                folder = os.path.normpath(os.path.join(os.path.dirname(sweeps_file), family[4:]))
                folders[os.path.basename(folder)] = folder
    return folders


def generate_arguments(run, with_reflex=None):
    """`polydecomp generate`'s arguments for a generated key's polygon. A key on a curve of the family's
    default r is made without --reflex, as the sweep made it; other keys with --reflex, unless with_reflex
    is False (a family whose r is an outcome refuses --reflex: made_again then makes it without). A
    family with holes has h in its keys, 0 included."""
    if with_reflex is None:
        with_reflex = not any("r=default" in label for label in run.curves)
    args = ["--family", run.family, "--n", str(run.n)]
    if with_reflex:
        args += ["--reflex", str(run.r)]
    if "/h:" in run.name:
        args += ["--holes", str(run.h)]
    return args + ["--seed", str(run.seed), "--format", "wkt"]


def polygon_input(run, corpora):
    """The corpus file of a corpus key (its folder from `corpora`, else CORPUS/FILE as the key names it),
    None for a generated key."""
    if run.file is None:
        return None
    return os.path.join(corpora.get(run.family, run.family), run.file)


def shown_path(path):
    """A corpus file's path as the commands show it: relative to the working folder when it lies inside."""
    relative = os.path.relpath(path)
    return path if relative.startswith(os.pardir) else relative


def polygon_source(run, corpora, made_by=None):
    """(the shell command that makes the key's polygon as polygon.wkt, or "" for a corpus file; the file
    `run --input` then reads): the page builds the commands that draw any key (`run --svg`) from them. A
    report written in a checkout names its corpus files from the checkout's top. made_by: the generate
    arguments that made the polygon again (made_again's), when it was."""
    source = polygon_input(run, corpora)
    if source is not None:
        return "", shlex.quote(shown_path(source))
    command = ["polydecomp", "generate"] + (made_by or generate_arguments(run)) + ["-o", "polygon.wkt"]
    return " ".join(shlex.quote(a) for a in command), "polygon.wkt"


def encode_pieces(pieces):
    """The pieces as text: per piece its size, then its vertex indices, each one character of ALPHABET, or
    past it ESCAPE and the index's two digits in base len(ALPHABET)."""
    base = len(ALPHABET)

    def code(i):
        if i >= base * base:
            raise ValueError("vertex index {} past what a drawing encodes".format(i))
        return ALPHABET[i] if i < base else ESCAPE + ALPHABET[i // base] + ALPHABET[i % base]

    return "".join(code(len(piece)) + "".join(code(i) for i in piece) for piece in pieces)


def decode_pieces(text):
    """The pieces of encode_pieces' text: its inverse, as the page's script reads it."""
    base, pieces, at = len(ALPHABET), [], 0

    def index():
        nonlocal at
        if text[at] == ESCAPE:
            at += 3
            return ALPHABET.index(text[at - 2]) * base + ALPHABET.index(text[at - 1])
        at += 1
        return ALPHABET.index(text[at - 1])

    while at < len(text):
        size = index()
        pieces.append([index() for _ in range(size)])
    return pieces


def coordinate(value):
    number = float(Fraction(value)) if isinstance(value, str) else float(value)
    return float("{:.{}g}".format(number, COORDINATE_DIGITS))


def flat(points):
    return [coordinate(c) for point in points for c in point]


def made_again(polydecomp, run, corpora, folder):
    """(the polygon file of the key's polygon or an error text, the generate arguments that made it or
    None): generated into `folder` (once per polygon, by its caller), or the key's corpus file."""
    source = polygon_input(run, corpora)
    if source is not None:
        return (source if os.path.isfile(source) else "its corpus file {} is not here".format(source)), None
    path = os.path.join(folder, "polygon-{}-{}-{}-{}-{}.wkt".format(run.family, run.n, run.r, run.h, run.seed))
    args = generate_arguments(run)
    done = subprocess.run([polydecomp, "generate"] + args + ["-o", path], capture_output=True, text=True)
    if done.returncode == USAGE_ERROR and "--reflex" in args:
        args = generate_arguments(run, with_reflex=False)
        done = subprocess.run([polydecomp, "generate"] + args + ["-o", path], capture_output=True, text=True)
    if done.returncode != 0:
        return done.stderr.strip() or "generate exited {}".format(done.returncode), None
    return path, args


def decomposition(polydecomp, run, polygon_file):
    """`run --json`'s object for the key, or an error text."""
    command = [polydecomp, "run", "--algorithm", run.algorithm, "--input", polygon_file, "--json",
               "--max-seconds", str(RUN_SECONDS)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=4 * RUN_SECONDS)
    except subprocess.TimeoutExpired:
        return "the run did not end within {} s".format(4 * RUN_SECONDS)
    if done.returncode not in (0, INVALID_RESULT):
        return done.stderr.strip() or "run exited {}".format(done.returncode)
    try:
        return json.loads(done.stdout)
    except ValueError:
        return "run printed no JSON object (exit {})".format(done.returncode)


def drawable(run):
    return run.timed and run.n <= DRAW_MAX_N


def draw(runs, polydecomp, corpora, progress=sys.stderr):
    """{run name: drawing or error text} of the drawable runs. A drawing is {"vertices": flat coordinates of
    the polygon's n vertices, "steiner": those of the Steiner points, "pieces": encode_pieces' text,
    "made_by": the generate arguments that made the polygon, None for a corpus file}."""
    chosen = [run for run in runs if drawable(run)]
    out = {}
    with tempfile.TemporaryDirectory(prefix="pd-drawings-") as folder:
        polygons = {}
        for run in chosen:
            if run.polygon not in polygons:
                polygons[run.polygon] = made_again(polydecomp, run, corpora, folder)

        def one(run):
            polygon_file, made_by = polygons[run.polygon]
            if not os.path.isfile(polygon_file):
                return run, "not drawn: " + polygon_file
            d = decomposition(polydecomp, run, polygon_file)
            if isinstance(d, str):
                return run, "not drawn: " + d
            if run.file is None and (d["n"], d["reflex"], d["holes"]) != (run.n, run.r, run.h):
                return run, "not drawn: the polygon made again has n = {}, r = {}, h = {}".format(
                    d["n"], d["reflex"], d["holes"])
            return run, {"vertices": flat(d["points"][:d["n"]]), "steiner": flat(d["points"][d["n"]:]),
                         "pieces": encode_pieces(d["pieces"]), "made_by": made_by}

        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
            for done, (run, drawing) in enumerate(pool.map(one, chosen), 1):
                out[run.name] = drawing
                if progress and (done % 1000 == 0 or done == len(chosen)):
                    print("report: drew {} of {} keys".format(done, len(chosen)), file=progress, flush=True)
    return out
