#!/usr/bin/python3
"""Makes docs/experiment.md's result tables from the committed results in docs/results/.

    /usr/bin/python3 docs/tables.py [--results DIR] [--doc FILE] [--print | --check]

Reads DIR/study.json (`elbowsim montecarlo scenarios/elbow_experiment.yaml`:
90 cases, three arms, paired ratios with 95 % BCa intervals), DIR/claim/*.json (the
nominal case under one change each: docs/results/claim/run.sh), DIR/sensitivity/*.json
and DIR/sensors/*.json (the sensors' axis: docs/results/sensors/run.sh), and rewrites
what lies between each marker pair of the document

    <!-- results:NAME -->
    ... (replaced) ...
    <!-- /results:NAME -->

(NAME: verdict, energy, hand, energy_balanced, hand_balanced, nominal, claim,
sensitivity, sensors) and nothing else. It prints the
ranges the prose quotes (savings, shares of draws), so the prose can be checked
against the data; each table also ends with them.

  --print   print the blocks and ranges, leave the document alone
  --check   exit 1 if the document's blocks differ from what the results give

Standard library only, like bench/tables.py.
"""

import argparse
import json
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from marked_blocks import marked, write_or_check  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ON, OFF, BALANCED = "elbow_on", "elbow_off", "elbow_off_balanced"

# The claim rows in table order: the file in claim/ and what it changes.
# The exact command of each is in claim/run.sh.
CLAIM_ROWS = [
    ("nothing", "nothing (the study's case, the table's height known exactly)"),
    ("lower", "table believed 1 mm lower (`controller.model`)"),
    ("higher", "table believed 1 mm higher"),
    ("lower005", "table believed 0.05 mm lower"),
    ("lower025", "table believed 0.25 mm lower"),
    ("higher025", "table believed 0.25 mm higher"),
    ("force60", "force control pushing 60 N on the elbow (`controller.type=force`)"),
    ("force5", "force control pushing 5 N"),
    ("pd", "the rule's gains without the feed-forward (`controller.type=pd`)"),
    ("jointfriction", "joint friction 0.1 N m Coulomb, 0.15 N m breakaway at every joint"),
    ("motors20", "the 20 W motors at every joint (3 times over their rating held out)"),
    ("continuous", "continuous control (no sampling, exact sensors; the rule without integral action)"),
    ("samegains", "the gains both arms once shared: Kp 50 V/rad, Kd 2 V s/rad, no integral "
                  "(`controller.tuning=null`)"),
    ("tunedpd", "the rule without integral action (`controller.tuning.integral=0`)"),
    ("tuned20", "the rule at 20 Hz (`controller.tuning.bandwidth=20`, step 0.25 ms)"),
    ("nogravity", "no gravity (`effects.gravity=false`)"),
    ("pad", "a rubber elbow pad, k 4e4 N/m, c 60 N s/m (`contact.pad`: 0.36 mm under the "
            "resting elbow's 14.5 N); the plan rests the elbow on the table's surface"),
    ("padplanned", "the same pad, the plan resting the elbow at its static depth (the table "
                   "believed 0.36 mm lower)"),
    ("padstiff", "a pad ten times stiffer, k 4e5 N/m, c 190 N s/m (0.036 mm)"),
    ("pad1e6", "a pad of 1.2e6 N/m, c 310 N s/m (0.012 mm)"),
    ("pad4e6", "a pad of 4e6 N/m, c 570 N s/m (0.0036 mm)"),
    ("sensors512", "coarse sensors: 512-count encoders, 1e-4 rad noise (step 0.125 ms)"),
]


def sig(x, digits=3):
    """x with `digits` significant digits, trailing zeros kept (0.130, 2.21, 0.0995)."""
    text = f"{x:#.{digits}g}"
    return text[:-1] if text.endswith(".") else text


def interval(x, ci):
    return f"{sig(x)} ({sig(ci[0])}–{sig(ci[1])})"


def percent(x):
    return f"{100 * x:.0f}"


def span(values, fmt):
    lo, hi = fmt(min(values)), fmt(max(values))
    return lo if lo == hi else f"{lo}–{hi}"


def mm(x_m):
    return sig(1e3 * x_m)


def rel(path):
    return os.path.relpath(path, ROOT)


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        sys.exit(f"tables.py: {path}: {e}")


def pair(doc, b=None):
    b = b or OFF
    pairs = doc.get("pairs") or []
    for p in pairs:
        if p.get("a") == ON and p.get("b") == b:
            return p
    sys.exit(f"tables.py: no {ON}/{b} pair in {doc.get('case', doc.get('scenario'))}")


def table(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    return out + ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]


# --- the study: 90 cases, three arms ---------------------------------------------

AXES = ("task", "speed", "elbow", "motor")


def cases_by_level(study):
    axes = {a["name"]: a["levels"] for a in study["axes"]}
    for name in AXES:
        if name not in axes:
            sys.exit(f"tables.py: study.json has no axis {name!r}")
    by = {}
    for c in study["cases"]:
        by[tuple(c["levels"][a] for a in AXES)] = c
    return axes, by


def study_header(path, study, what):
    return (f"Generated by `docs/tables.py` from `{rel(path)}` (`elbowsim montecarlo "
            f"{study['file']}`, seed {study['seed']}, {study['samples']} draws per case, "
            f"{len(study['cases'])} cases): {what}")


ELBOW_HEAD = {"near": "near (34 cm)", "mid": "mid (40 cm)", "far": "far (46 cm)"}
MOTOR_HEAD = {"sized": "sized motors", "large": "150 W motors"}


def ratio_table(path, study, metric, b, what, ranges):
    axes, by = cases_by_level(study)
    columns = [(e, m) for m in axes["motor"] for e in axes["elbow"]]
    head = ["task", "speed"] + [f"{MOTOR_HEAD.get(m, m)}, elbow {ELBOW_HEAD.get(e, e)}"
                                for e, m in columns]
    rows = []
    for task in axes["task"]:
        for speed in axes["speed"]:
            row = [task, speed]
            for elbow, motor in columns:
                p = pair(by[task, speed, elbow, motor], b)[metric]
                cell = interval(p["ratio"], p["ci95"]) if "ratio" in p else p["outcome"]
                if p.get("outcome") not in ("lower", None):
                    cell += f" **{p['outcome']}**"
                if p.get("pairs", study["samples"]) < study["samples"]:
                    cell += f", {p['pairs']} pairs"
                row.append(cell)
            rows.append(row)
    return ([study_header(path, study, what), ""] + table(head, rows) + ["", "Ranges in these data: "
            + "; ".join(f"{k} {v}" for k, v in ranges.items()) + "."])


def corrected(study, metric, b):
    """The study's Holm-corrected count and the draws each side wins (study.json's tally)."""
    for t in study.get("tally", []):
        if t.get("a") == ON and t.get("b") == b:
            c = t["corrected"][metric]
            d = c["draws"]
            return (f"lower in {len(c['lower'])}, higher in {len(c['higher'])}, not significant in "
                    f"{len(c['not significant'])} of {c['tests']}; resting lower in "
                    f"{d['a_lower']} of {d['a_lower'] + d['b_lower']} draws")
    sys.exit(f"tables.py: study.json has no corrected tally for {ON}/{b}")


def study_ranges(study, b):
    """The numbers the prose quotes about elbow_on against `b`, from every case."""
    _, by = cases_by_level(study)
    select = lambda test: [c for k, c in by.items() if test(*k)]
    moving = select(lambda t, s, e, m: t != "hold")
    hold = select(lambda t, s, e, m: t == "hold")
    e = lambda cs: [pair(c, b)["energy_drawn"]["ratio"] for c in cs]
    h = lambda cs: [pair(c, b)["hand_error_rms"]["ratio"] for c in cs]
    win = lambda cs, m: [pair(c, b)[m]["win_rate"] for c in cs]
    ratios = lambda rs: span(rs, sig)
    mean = lambda cs, v: [c["metrics"][v]["hand_error_rms"]["mean"] for c in cs]
    samples = study["samples"]
    energy = {"energy ratio, every case": ratios(e(by.values()))}
    for motor in ("sized", "large"):
        energy[f"{motor} motors"] = ratios(e(select(lambda t, s, el, m: m == motor)))
    energy["hold"] = ratios(e(hold))
    energy["cases where the resting elbow drew less in every draw"] = (
        f"{sum(w == 1 for w in win(by.values(), 'energy_drawn'))} of {len(by)}")
    energy["after Holm's correction"] = corrected(study, "energy_drawn", b)
    hand = {
        "RMS hand error ratio, moving tasks": ratios(h(moving)),
        "draws where the resting elbow is more accurate, moving tasks":
            span(win(moving, "hand_error_rms"), percent) + " %",
        "hold": ratios(h(hold)) + ", in " + span([round(w * samples) for w in
                                                  win(hold, "hand_error_rms")], str)
        + f" of {samples} draws, mean {span(mean(hold, b), mm)} mm against "
        f"{span(mean(hold, ON), mm)} mm resting",
        "after Holm's correction (sign tests over the cases)": corrected(study, "hand_error_rms", b),
    }
    return energy, hand


def run_ranges(study):
    """What every case shares: the accuracy floors, the smallest error, the invalid runs."""
    _, by = cases_by_level(study)
    floors = [f for c in by.values() for f in c["accuracy_floor"].values()]
    medians = [m["hand_error_rms"]["median"] for c in by.values() for m in c["metrics"].values()]
    return {"largest accuracy floor": f"{sig(1e6 * max(floors))} µm",
            "smallest median RMS hand error": f"{sig(1e6 * min(medians))} µm",
            "invalid runs": str(sum(c["invalid_runs"] for c in by.values()))}


def verdict_block(path, study):
    lines = [f"Generated by `docs/tables.py` from `{rel(path)}`: the verdict "
             f"`elbowsim montecarlo` prints over the {len(study['cases'])} cases.", ""]
    return lines + [f"- {v}" for v in study["verdict"]]


# --- the nominal case and the claim's limits ----------------------------------------


NOMINAL = ("loops", "nominal", "mid", "sized")


def nominal_block(path, study):
    _, by = cases_by_level(study)
    case = by[NOMINAL]
    rows = []
    for v, m in case["metrics"].items():
        q = lambda name, scale=1.0, unit="J": (
            f"{sig(scale * m[name]['mean'])} {unit} ({sig(scale * m[name]['ci95'][0])}–"
            f"{sig(scale * m[name]['ci95'][1])})")
        rows.append([v, q("energy_drawn"), q("energy_in"), q("hand_error_rms", 1e3, "mm")])
    head = ["variant", "drawn from the supply", "net energy in", "RMS hand error"]
    return ([f"Generated by `docs/tables.py` from `{rel(path)}` (case {case['case']}, "
             f"{study['samples']} draws, seed {study['seed']}): means over the draws with their "
             f"95 % BCa intervals.", ""] + table(head, rows))


def claim_cell(p, samples):
    if "ratio" not in p:
        return None
    cell = interval(p["ratio"], p["ci95"])
    outcome = p["outcome"]
    if outcome != "lower":
        cell = f"**{outcome}**: {cell}"
    if p["pairs"] < samples:
        cell += f", {p['pairs']} draws"
    return cell


def claim_block(folder):
    rows, notes = [], []
    for name, label in CLAIM_ROWS:
        path = os.path.join(folder, name + ".json")
        doc = load(path)
        p = pair(doc)
        energy = claim_cell(p["energy_drawn"], doc["samples"])
        if energy is None:
            reason = p["energy_drawn"].get("reason", "")
            rows.append([label, f"{p['energy_drawn']['outcome']}: {reason} "
                         f"({len(doc['invalid'])} of {len(doc['variants']) * doc['samples']} runs invalid)", "", ""])
            continue
        hand = claim_cell(p["hand_error_rms"], doc["samples"])
        means = ", ".join(f"{mm(doc['metrics'][v]['hand_error_rms']['mean'])} mm"
                          for v in (ON, OFF))
        # montecarlo.json counts slips since 2026-12-07 (older rows have no "slips").
        slipped = doc.get("slips", {}).get(ON, {})
        if slipped.get("draws_with_slips", 0):
            label += (f"; the resting elbow slipped in {slipped['draws_with_slips']} of "
                      f"{doc['samples']} draws, {slipped['median']} slip "
                      f"event{'' if slipped['median'] == 1 else 's'} a run (median)")
        rows.append([label, energy, hand, means])
        if doc["invalid"]:
            notes.append(f"{name}: {len(doc['invalid'])} invalid runs ("
                         + ", ".join(sorted({i['variant'] for i in doc['invalid']})) + ")")
    head = ["what changes", "energy drawn on / off", "RMS hand error on / off",
            "RMS hand error (mean), on and off"]
    first = load(os.path.join(folder, CLAIM_ROWS[0][0] + ".json"))
    lines = [f"Generated by `docs/tables.py` from `{rel(folder)}/*.json` (`elbowsim montecarlo "
             f"scenarios/elbow_experiment.yaml --case {first['case']} --variants {ON},{OFF}` with "
             f"the table's height known exactly and each change, `{rel(folder)}/run.sh`; "
             f"{first['samples']} draws, seed {first['seed']}): paired ratios on / off (geometric "
             f"mean over the draws) with 95 % BCa intervals; all runs valid unless said.", ""]
    lines += table(head, rows)
    if notes:
        lines += ["", "Invalid runs: " + "; ".join(notes) + "."]
    return lines


# The table box's centre height in scenarios/elbow_experiment.yaml: what the controller
# believes; a held table height is shown as its offset from it.
TABLE_Z = -0.0998938
SENSITIVITY_RUNS = [("shipped", "the study's uncertainty (the table's height ±0.1 mm)"),
                    ("tableknown", "the table's height known exactly"),
                    ("pad", "the table known, a compliant elbow pad of 4e5–4e6 N/m")]


def sensitivity_cell(point):
    if "ratio" not in point:
        return point.get("outcome", "no verdict")
    cell = interval(point["ratio"], point["ci95"]) if "ci95" in point else sig(point["ratio"])
    return cell if point["outcome"] == "lower" else f"{cell}, {point['outcome']}"


def sensitivity_block(folder):
    rows = []
    first = None
    for name, label in SENSITIVITY_RUNS:
        doc = load(os.path.join(folder, name + ".json"))
        first = first or doc
        for m in doc["metrics"]:
            what = "energy drawn" if m["metric"] == "energy_drawn" else "RMS hand error"
            rows.append([f"{label}: {what}", "every parameter drawn",
                         sensitivity_cell(m["nominal"]), "", ""])
            for f in m["factors"]:
                def end(e):
                    v = f[e]["value"]
                    at = (f"{v * 100:+.0f} %" if "range" not in f["law"]
                          else f"{(v - TABLE_Z) * 1e3:+.2f} mm" if f["given"].startswith("table.")
                          else f"{v:.2g}".replace("e+0", "e").replace("e+", "e"))
                    return f"{at.replace('-', '−')}: {sensitivity_cell(f[e])}"
                effect = f["effect"] + ("" if f.get("monotone", True) else ", not monotone")
                rows.append(["", f"`{f['given']}`", end("low"), end("high"), effect])
    head = ["run: ratio", "held", "low end", "high end", "effect on the verdict"]
    lines = [f"Generated by `docs/tables.py` from `{rel(folder)}/*.json` (`elbowsim sensitivity "
             "scenarios/elbow_experiment.yaml --case task=loops,speed=nominal,elbow=mid,motor=sized`, "
             f"`{rel(folder)}/run.sh`; {first['samples']} draws per point, seed {first['seed']}): "
             "paired ratios on / off (the resting against the held-up arm; geometric mean over the "
             "draws) with 95 % BCa intervals, every uncertain parameter drawn, then each held at an end of its range (the table's "
             "height as its offset from where the controller believes it), the others drawn on "
             "the same draws.", ""] + table(head, rows)
    return lines


# --- the sensors' axis, rigid and padded ----------------------------------------------

SENSOR_RUNS = [("rigid", "rigid contact (the study's model)"),
               ("pad", "an elbow pad of 4e5–4e6 N/m, drawn")]
SENSOR_HEAD = {"fine": "fine (4096 counts, 1e-5 rad)", "coarse": "coarse (512 counts, 1e-4 rad)"}


def sensor_rows(doc):
    """One row per case of a sensors study: the ratios against both other arms and the slips."""
    rows, samples = [], doc["samples"]
    for c in doc["cases"]:
        cells = []
        for b in (OFF, BALANCED):
            p = pair(c, b)
            for m in ("energy_drawn", "hand_error_rms"):
                x = p[m]
                cell = interval(x["ratio"], x["ci95"]) if "ci95" in x else x.get("outcome", "no verdict")
                if x.get("outcome") not in ("lower", None) and "ci95" in x:
                    cell += f" **{x['outcome']}**"
                cells.append(cell)
        slips = c.get("slips", {}).get(ON, {})
        slipped = (f"{slips['draws_with_slips']} of {samples}, median {slips['median']}"
                   if slips.get("draws_with_slips") else "none")
        levels = c["levels"]
        rows.append([levels["task"], SENSOR_HEAD.get(levels["sensors"], levels["sensors"])]
                    + cells + [slipped, str(c["invalid_runs"])])
    return rows


def sensors_block(folder):
    lines = []
    for name, label in SENSOR_RUNS:
        path = os.path.join(folder, name + ".json")
        doc = load(path)
        if not lines:
            lines = [f"Generated by `docs/tables.py` from `{rel(folder)}/*.json` (`elbowsim "
                     f"montecarlo {doc['file']} --case speed=nominal,elbow=mid,motor=sized` with "
                     f"the axis `sensors` added, `{rel(folder)}/run.sh`; {doc['samples']} draws per "
                     f"case, seed {doc['seed']}, each case's plants its own): paired ratios (geometric "
                     "mean over the draws) with 95 % BCa intervals, below 1 the resting elbow draws "
                     "less or is more accurate; slips: the draws in which the resting elbow began "
                     "to slide after sticking, and the median slip events a run.", ""]
        lines += [f"**{label}** ({len(doc['cases'])} cases):", ""]
        head = ["task", "sensors", f"energy on / off", "hand error on / off",
                "energy on / balanced", "hand error on / balanced", "resting elbow slipped",
                "invalid runs"]
        lines += table(head, sensor_rows(doc)) + [""]
        # The net energy's lines say what the drawn energy's do here: left out.
        lines += [f"- {v}" for v in doc["verdict"] if not v.startswith("Net electrical")] + [""]
    return lines[:-1]


# --- the document ----------------------------------------------------------------


def build_blocks(folder):
    study_path = os.path.join(folder, "study.json")
    study = load(study_path)
    claim = os.path.join(folder, "claim")
    blocks, ranges = {"verdict": verdict_block(study_path, study)}, {}
    for b, name, who in ((OFF, "", "the held-up arm"), (BALANCED, "_balanced", "the counterbalanced arm")):
        energy_ranges, hand_ranges = study_ranges(study, b)
        blocks["energy" + name] = ratio_table(
            study_path, study, "energy_drawn", b,
            f"paired ratios of the energy drawn from the supply, {ON} / {b} (geometric mean over "
            f"the draws), with 95 % BCa intervals; below 1 the resting elbow draws less than "
            f"{who}.", energy_ranges)
        blocks["hand" + name] = ratio_table(
            study_path, study, "hand_error_rms", b,
            f"paired ratios of the RMS hand error, {ON} / {b}, with 95 % BCa intervals; below 1 "
            f"the resting elbow is more accurate than {who}.", hand_ranges)
        ranges[f"energy on/{b}"], ranges[f"hand on/{b}"] = energy_ranges, hand_ranges
    ranges["every run"] = run_ranges(study)
    blocks["nominal"] = nominal_block(study_path, study)
    blocks["claim"] = claim_block(claim)
    blocks["sensitivity"] = sensitivity_block(os.path.join(folder, "sensitivity"))
    blocks["sensors"] = sensors_block(os.path.join(folder, "sensors"))
    return blocks, ranges


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--results", default=os.path.join(ROOT, "docs", "results"),
                    help="folder with study.json and claim/*.json (default: docs/results)")
    ap.add_argument("--doc", default=os.path.join(ROOT, "docs", "experiment.md"),
                    help="the document to update (default: docs/experiment.md)")
    mode = ap.add_mutually_exclusive_group()
    mode.add_argument("--print", action="store_true", help="print, do not write the document")
    mode.add_argument("--check", action="store_true", help="exit 1 if the document is out of date")
    args = ap.parse_args()

    blocks, ranges = build_blocks(os.path.abspath(args.results))
    print("ranges (what the prose may quote):")
    for table_name, r in ranges.items():
        for k, v in r.items():
            print(f"  {table_name:28s} {k}: {v}")
    if args.print:
        for name, lines in blocks.items():
            print("\n" + marked("results", name, lines))
        return 0
    return write_or_check(args.doc, rel(args.doc), blocks, "results", args.check,
                          "result tables", rel(args.results))

if __name__ == "__main__":
    sys.exit(main())
