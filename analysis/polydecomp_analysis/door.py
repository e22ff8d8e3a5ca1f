"""The door's costs (polydecomp-door-bench's JSON) as a Markdown table: per family, reading against the
floor of a plain number scan, the checked constructor against the fastest triangulation, each
triangulation's validation against the triangulation, and `polydecomp run` end to end against
`monotone`, each with the target of issue 34 it is held to."""

TRIANGULATIONS = ("monotone", "seidel", "cutting-tri", "cgal-cdt")
TARGETS = {"read": 1.5, "check": 1.0, "validate": 2.0, "run": 3.0}


def medians(benchmarks):
    """{(part, family): seconds, peak bytes} from Google Benchmark's entries: the median aggregate where
    repetitions were run, else the single run; wall time for `run-monotone`, CPU time for the rest."""
    out = {}
    for b in benchmarks:
        if b.get("error_occurred"):
            continue
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        name = b["run_name"] if "run_name" in b else b["name"]
        part, _, family = name.partition("/")
        family = family.split("/")[0]
        unit = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
        seconds = b["real_time" if part == "run-monotone" else "cpu_time"] * unit
        out[(part, family)] = (seconds, b.get("peak_bytes"))
    return out


def ratio_cell(value, floor, target):
    if value is None or not floor:
        return "-"
    ratio = value / floor
    return "{:.2f}x".format(ratio) if ratio <= target else "**{:.2f}x**".format(ratio)


def seconds_cell(value):
    return "-" if value is None else "{:.3f}".format(value)


def family_row(family, m):
    get = {part: value for (part, of), value in m.items() if of == family}
    scan = get.get("scan", (None, None))[0]
    triangulations = {t: get[t][0] for t in TRIANGULATIONS if t in get}
    fastest = min(triangulations.values()) if triangulations else None
    row = [family, seconds_cell(scan)]
    for fmt in ("txt", "wkt", "geojson"):
        read = get.get("read-" + fmt, (None, None))
        row.append("{} ({})".format(seconds_cell(read[0]), ratio_cell(read[0], scan, TARGETS["read"]))
                   if read[0] is not None and scan else seconds_cell(read[0]))
    txt_peak = get.get("read-txt", (None, None))[1]
    row.append("-" if txt_peak is None else "{:.1f}".format(txt_peak / 1e6))
    check = get.get("check", (None, None))[0]
    row.append("{} ({})".format(seconds_cell(check), ratio_cell(check, fastest, TARGETS["check"])))
    for t in TRIANGULATIONS:
        run = triangulations.get(t)
        validation = get.get("validate-" + t, (None, None))[0]
        row.append("-" if run is None else "{} / {} ({})".format(
            seconds_cell(run), seconds_cell(validation), ratio_cell(validation, run, TARGETS["validate"])))
    end_to_end = get.get("run-monotone", (None, None))[0]
    row.append("-" if end_to_end is None else "{} ({})".format(
        seconds_cell(end_to_end), ratio_cell(end_to_end, triangulations.get("monotone"), TARGETS["run"])))
    return row


def door_table(document):
    """Markdown for a polydecomp-door-bench JSON document (its context, then one row per family)."""
    m = medians(document["benchmarks"])
    families = []
    for _, family in m:
        if family not in families:
            families.append(family)
    context = document.get("context", {})
    lines = ["Measured by `polydecomp-door-bench` (`make door`): commit {}, {}, CGAL {}, {} build, {}.".format(
        context.get("git_commit", "?"), context.get("compiler", "?"), context.get("cgal_version", "?"),
        context.get("build_type", "?"), context.get("cpu", context.get("host_name", "?"))),
        "Seconds, CPU time of the part alone (median of the repetitions); `run` is wall time of the process.",
        "Ratios: reading to the scan (target {read}x), the check to the fastest triangulation ({check}x),"
        " validation to its triangulation ({validate}x), `run` to `monotone` ({run}x); in bold where over"
        " the target.".format(**TARGETS),
        "",
        "| family | scan | read txt | read wkt | read geojson | txt peak MB | check | " +
        " | ".join(t + " / validation" for t in TRIANGULATIONS) + " | run monotone |",
        "|" + "---|" * (8 + len(TRIANGULATIONS))]
    for family in families:
        lines.append("| " + " | ".join(family_row(family, m)) + " |")
    return "\n".join(lines) + "\n"
