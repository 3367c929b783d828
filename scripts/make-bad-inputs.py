#!/usr/bin/env python3
"""Writes the bad-input catalogue: tests/data/bad/<case files> and
tests/data/bad/catalogue.tsv (one case per line: name, CLI arguments, the
fragments the one-line refusal must contain, separated by '|').

Run from the repository root: python3 scripts/make-bad-inputs.py
The generated files are committed; tests/app/bad_input_catalogue_test.cpp
runs every case against the real CLI (exit 2, message, <200 MB, <2 s).

Placeholders in the arguments, filled in by the test:
  {bad}  a temporary copy of tests/data/bad   {res}  the resources folder
  {tmp}  a scratch folder                      {fifo} a named pipe made by the test
The CLI runs in {bad}, so a plan may name a profile file there by its name.
"""
import copy
import json
import os
import shutil
import struct

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "tests", "data", "bad")
RES = os.path.join(ROOT, "resources")
cases = []
# Keys read before the file's schema is applied (they choose the reader): a
# typo there is "missing required field", tested once each below.
REQUIRED_FIRST = {"type", "method", "vehicle"}


def load(rel):
    with open(os.path.join(RES, rel)) as f:
        return json.load(f)


def write(name, text):
    with open(os.path.join(OUT, name), "w", newline="") as f:
        f.write(text)


def write_bytes(name, data):
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)


def case(name, args, *expect):
    assert "\t" not in args and name not in {c[0] for c in cases}, name
    cases.append((name, args, "|".join(expect)))


def typo(key):
    """A plausible misspelling: the middle character typed twice ("instaalled_kg").
    (Dropping a character is ambiguous for keys such as disk_A_top/disk_B_top.)"""
    i = len(key) // 2
    return key[:i] + key[i] + key[i:]


def object_paths(doc, path=()):
    """Every (path, key) of every object in the document, arrays by their first element."""
    if isinstance(doc, dict):
        for k, v in doc.items():
            yield path, k
            yield from object_paths(v, path + (k,))
    elif isinstance(doc, list) and doc and isinstance(doc[0], (dict, list)):
        yield from object_paths(doc[0], path + (0,))


def node(doc, path):
    for p in path:
        doc = doc[p]
    return doc


def json_path(path, key):
    s = ""
    for p in path:
        s += "[%d]" % p if isinstance(p, int) else ("." if s else "") + p
    return s + ("." if s else "") + key


def misspelt_variants(prefix, doc, command, skip=()):
    n = 0
    for path, key in object_paths(doc):
        if key in skip or any(p in skip for p in path if isinstance(p, str)) or len(key) < 2 or key in REQUIRED_FIRST:
            continue  # one-letter keys have no unambiguous typo; REQUIRED_FIRST are read before the schema
        bad = copy.deepcopy(doc)
        obj = node(bad, path)
        t = typo(key)
        if t in obj:
            continue
        # keep the order of keys: rebuild the object with the one key renamed
        items = [(t if k == key else k, v) for k, v in obj.items()]
        obj.clear()
        obj.update(items)
        name = "%s_typo_%s.json" % (prefix, json_path(path, key).replace(".", "_").replace("[", "_").replace("]", ""))
        write(name, json.dumps(bad, indent=2) + "\n")
        case(name[:-5], command.format(f="{bad}/" + name), name, json_path(path, t), "did you mean " + key + "?",
             "remove or rename")
        n += 1
    return n


def replaced(doc, path, value):
    bad = copy.deepcopy(doc)
    node(bad, path[:-1])[path[-1]] = value
    return bad


def huge_number_variant(prefix, doc, path, command):
    text = json.dumps(replaced(doc, path, 12345.678), indent=2).replace("12345.678", "1e999")
    name = "%s_1e999_%s.json" % (prefix, "_".join(str(p) for p in path))
    write(name, text + "\n")
    line = text[: text.index("1e999")].count("\n") + 1
    case(name[:-5], command.format(f="{bad}/" + name), name + ":%d:" % line, "1e999", "beyond the range of a double",
         "physical value")


def value_variant(prefix, doc, path, value, command, *expect):
    name = "%s_%s_%s.json" % (prefix, "_".join(str(p) for p in path), str(value).replace(".", "p").replace("-", "m")
                               .replace(" ", "").replace("[", "").replace("]", "").replace(",", "_"))
    write(name, json.dumps(replaced(doc, path, value), indent=2) + "\n")
    case(name[:-5], command.format(f="{bad}/" + name), name, *expect)


def plan_doc_for_type():
    return load("examples/hugin1000_ballast_error.plan.json")


def main():
    if os.path.isdir(OUT):
        shutil.rmtree(OUT)
    os.makedirs(OUT)

    # ---- crane weighing file (first-mission --weighing) ----
    crane = load("examples/hugin1000_first_mission.json")
    crane_cmd = "first-mission --weighing {f}"
    misspelt_variants("crane", crane, crane_cmd)
    for p in [("total_kg",), ("scales_kg", "fore_port"), ("rope_x_m", "aft"), ("water", "salinity_psu"), ("rope_y_m",),
              ("water", "depth_m")]:
        huge_number_variant("crane", crane, p, crane_cmd)
    value_variant("crane", crane, ("installed_kg",), [43.2, 14.4, 19.2, 19.2], crane_cmd, "installed_kg",
                  "fore_starboard", "capacity 40 kg", "check the value")
    value_variant("crane", crane, ("installed_kg",), [300000, 0, 0, 0], crane_cmd, "installed_kg", "capacity",
                  "check the value")
    value_variant("crane", crane, ("installed_kg",), [1e308, 0, 0, 0], crane_cmd, "installed_kg", "capacity")
    value_variant("crane", crane, ("installed_kg",), [-1.2, 0, 0, 0], crane_cmd, "installed_kg",
                  "not a mass that can be installed", "0 or more")
    value_variant("crane", crane, ("installed_kg",), [1.2, 0, 0], crane_cmd, "installed_kg", "has 3 values",
                  "one mass in kg per point")
    value_variant("crane", crane, ("water", "temperature_degC"), 400, crane_cmd, "water.temperature_degC",
                  "out of range", "between -2 and 40")
    value_variant("crane", crane, ("water", "salinity_psu"), -3, crane_cmd, "water.salinity_psu", "between 0 and 42")
    value_variant("crane", crane, ("water", "latitude_deg"), 123, crane_cmd, "water.latitude_deg", "between -90 and 90")
    value_variant("crane", crane, ("water", "depth_m"), 20000, crane_cmd, "water.depth_m", "between 0 and 11000")
    value_variant("crane", crane, ("total_kg",), 1e6, crane_cmd, "total_kg", "out of range")
    value_variant("crane", crane, ("total_kg",), "1565.2", crane_cmd, "total_kg", "expected a number",
                  "plain number")
    value_variant("crane", crane, ("scales_kg", "aft_port"), -390.3, crane_cmd, "scales_kg.aft_port", "out of range")
    value_variant("crane", crane, ("total_kg",), 1500.0, crane_cmd, "scales", "more than 5 x the 2.00 kg tolerance",
                  "agree within 10.00 kg to be used")
    value_variant("crane", crane, ("use_optional_pieces",), "yes", crane_cmd, "use_optional_pieces",
                  "true or false")
    value_variant("crane", crane, ("method",), "hook", crane_cmd, "hook", "not supported", "crane")
    value_variant("crane", crane, ("vehicle",), "hugin9000", crane_cmd, "unknown vehicle 'hugin9000'", "use one of")
    value_variant("crane", crane, ("water",), None, crane_cmd, "water", "missing required field", "add \"water\"")
    text = json.dumps(crane, indent=2).replace('"total_kg": 1565.2,', '"total_kg": 1565.2,,')
    write("crane_syntax_error.json", text)
    case("crane_syntax_error", crane_cmd.format(f="{bad}/crane_syntax_error.json"),
         "crane_syntax_error.json:%d:" % (text[: text.index(",,")].count("\n") + 1), "invalid JSON", "fix the syntax")
    for key in ("method", "vehicle"):
        bad = {(k + k[len(k) // 2] if k == key else k): v for k, v in crane.items()}
        write("crane_misspelt_required_%s.json" % key, json.dumps(bad, indent=2))
        case("crane_misspelt_required_" + key, crane_cmd.format(f="{bad}/crane_misspelt_required_%s.json" % key),
             "crane_misspelt_required_%s.json" % key, key + ": missing required field", 'add "%s"' % key)
    bad = copy.deepcopy(plan_doc_for_type())
    bad["legs"][0] = {("tyype" if k == "type" else k): v for k, v in bad["legs"][0].items()}
    write("plan_misspelt_required_leg_type.json", json.dumps(bad, indent=2))
    case("plan_misspelt_required_leg_type", "simulate --vehicle hugin1000 --plan {bad}/plan_misspelt_required_leg_type.json"
         " --out {tmp}/o.csv", "plan_misspelt_required_leg_type.json", "legs[0].type: missing required field")
    write("crane_empty.json", "")
    case("crane_empty", crane_cmd.format(f="{bad}/crane_empty.json"), "crane_empty.json:1:1", "invalid JSON")
    write("crane_array.json", "[1, 2, 3]\n")
    case("crane_array", crane_cmd.format(f="{bad}/crane_array.json"), "crane_array.json", "expected a JSON object")
    write("crane_truncated.json", json.dumps(crane, indent=2)[:200])
    case("crane_truncated", crane_cmd.format(f="{bad}/crane_truncated.json"), "crane_truncated.json:", "invalid JSON")
    write("crane_long_key.json", json.dumps(dict(crane, **{"k" * 100000: 1})))
    case("crane_long_key", crane_cmd.format(f="{bad}/crane_long_key.json"), "crane_long_key.json", "unknown field",
         "remove or rename")
    write("crane_deep_nesting.json", "[" * 100000 + "]" * 100000)
    case("crane_deep_nesting", crane_cmd.format(f="{bad}/crane_deep_nesting.json"), "crane_deep_nesting.json",
         "expected a JSON object")
    case("crane_is_folder", crane_cmd.format(f="{bad}"), "is a folder, not a JSON file", "path of the .json file")
    case("crane_is_device", crane_cmd.format(f="/dev/zero"), "/dev/zero", "not a regular file", "path of the .json")
    case("crane_is_fifo", crane_cmd.format(f="{fifo}"), "not a regular file (FIFO", "path of the .json")
    case("crane_missing_file", crane_cmd.format(f="{bad}/no_such_file.json"), "no_such_file.json", "cannot open",
         "check the path")

    # ---- Slocum tank weighing file ----
    tank = load("examples/slocum_tank_weighing.json")
    misspelt_variants("tank", tank, crane_cmd)
    for p in [("dry_mass_kg",), ("tank", "bow_scale_g"), ("target", "density_kgm3"), ("ballast_g", "fore_port")]:
        huge_number_variant("tank", tank, p, crane_cmd)
    value_variant("tank", tank, ("dry_mass_kg",), 5000, crane_cmd, "dry_mass_kg", "between 1 and 1000")
    value_variant("tank", tank, ("tank", "water"), "brackish", crane_cmd, "tank.water", "fresh", "salt")
    value_variant("tank", tank, ("target", "temperature_degC"), 99, crane_cmd, "target.temperature_degC",
                  "out of range")

    # ---- vehicle profile (crane flags load it first) ----
    hugin = load("vehicles/hugin1000.json")
    flags = ("first-mission --vehicle {f} --scales 392.3,391.3,391.3,390.3 --total 1565.2 --rope-x 1.3422,-1.6578 "
             "--temperature 6.5 --salinity 34.5")
    misspelt_variants("profile", hugin, flags)
    for p in [("mass_in_air_kg",), ("bg_mm",), ("hull", "length_m"), ("adjustment_points", 0, "capacity_kg")]:
        huge_number_variant("profile", hugin, p, flags)
    value_variant("profile", hugin, ("kind",), "submarine", flags, "kind", "unknown vehicle kind", "auv")
    value_variant("profile", hugin, ("bg_mm",), 5000, flags, "bg_mm", "between -500 and 500")
    value_variant("profile", hugin, ("hull", "diameter_m"), 0, flags, "hull.diameter_m", "out of range")

    # ---- simulation sections of a profile (simulate loads them) ----
    delphin = load("vehicles/delphin2.json")
    hover_plan = load("examples/delphin2_hover.plan.json")

    def sim_case(name):
        """A plan naming profile `name` (simulate refuses --vehicle PATH against a plan's id)."""
        write("plan_for_" + name, json.dumps(dict(hover_plan, vehicle=name), indent=2) + "\n")
        return "simulate --plan {bad}/plan_for_%s --out {tmp}/out.csv" % name

    sub = {k: delphin[k] for k in delphin}
    n = 0
    for path, key in object_paths(delphin):
        if not path or path[0] not in ("hydrodynamics", "actuators", "sim_assumptions", "autopilot"):
            continue
        if n % 3 == 0 or len(path) > 1:  # a sample of every section and every nested object
            bad = copy.deepcopy(sub)
            obj = node(bad, path)
            t = typo(key)
            items = [(t if k == key else k, v) for k, v in obj.items()]
            obj.clear()
            obj.update(items)
            name = "simprofile_typo_%s.json" % json_path(path, key).replace(".", "_")
            write(name, json.dumps(bad, indent=2) + "\n")
            case(name[:-5], sim_case(name), name, json_path(path, t), "did you mean " + key + "?")
        n += 1
    huge_number_variant("simprofile", delphin, ("hydrodynamics", "Iyy_kgm2"),
                        sim_case("simprofile_1e999_hydrodynamics_Iyy_kgm2.json").replace("{", "{{").replace("}", "}}"))

    # ---- mission plan (simulate --plan) ----
    plan = load("examples/hugin1000_ballast_error.plan.json")
    plan_cmd = "simulate --vehicle hugin1000 --plan {f} --out {{tmp}}/out.csv"
    misspelt_variants("plan", plan, plan_cmd)
    survey = load("examples/hugin1000_survey.plan.json")
    misspelt_variants("plan_survey", survey, plan_cmd, skip=("legs", "format", "version", "vehicle", "description"))
    hover = load("examples/delphin2_hover.plan.json")
    misspelt_variants("plan_hover", {k: hover[k] for k in ("format", "version", "vehicle", "water", "legs", "options")},
                      plan_cmd.replace("hugin1000", "delphin2"), skip=("legs", "format", "version", "vehicle", "water"))
    for p in [("installed_kg", 0), ("water", "cast", 0, "depth_m"), ("legs", 0, "duration_s"),
              ("ballast_error", "net_buoyancy_kg")]:
        huge_number_variant("plan", plan, p, plan_cmd)
    value_variant("plan", plan, ("installed_kg",), [300000, 0, 0, 0], plan_cmd, "installed_kg", "capacity",
                  "check the value")
    value_variant("plan", plan, ("installed_kg",), [43.2, 7.2, 25.2, 25.2], plan_cmd, "installed_kg",
                  "capacity 40 kg")
    value_variant("plan", plan, ("installed_kg",), [-7.2, 7.2, 25.2, 25.2], plan_cmd, "installed_kg",
                  "not a mass that can be installed")
    value_variant("plan", plan, ("legs", 0, "duration_s"), 1e9, plan_cmd, "legs[0].duration_s", "out of range")
    value_variant("plan", plan, ("legs", 0, "type"), "loiter", plan_cmd, "legs[0].type", "unknown leg type")
    value_variant("plan", plan, ("legs",), [], plan_cmd, "legs", "no legs", "add at least one")
    value_variant("plan", plan, ("format",), "mission", plan_cmd, "format", "not a mission plan")
    value_variant("plan", plan, ("options", "dt_s"), 0, plan_cmd, "options.dt_s", "out of range")
    value_variant("plan", plan, ("water", "cast", 0, "temperature_degC"), 300, plan_cmd,
                  "water.cast[0].temperature_degC", "out of range")

    # ---- analysis report given to plan ----
    report = {"vehicle": "hugin1000", "vehicle_kind": "auv", "net_buoyancy_kg": 1.2, "net_buoyancy_sigma_kg": 0.1,
              "cg_offset_mm": {"x": 2.0, "y": 0.5}, "cg_offset_sigma_mm": {"x": 0.5, "y": 0.2},
              "errors": {"depth_m": 0.1, "pitch_deg": 0.2, "roll_deg": 0.1},
              "water": {"temperature_degC": 8.0, "salinity_psu": 35.0, "depth_m": 50.0}}
    rep_cmd = ("plan --vehicle hugin1000 --config 1-2-3 --report {f} --installed 7.2,7.2,25.2,25.2 --no-save "
               "--temperature 8 --salinity 35 --depth 50")
    misspelt_variants("report", report, rep_cmd)
    huge_number_variant("report", report, ("net_buoyancy_kg",), rep_cmd)
    value_variant("report", report, ("vehicle",), "slocum_g2", rep_cmd, "report_vehicle_slocum_g2.json",
                  "analyses vehicle 'slocum_g2', not 'hugin1000'", "analysed vehicle")
    value_variant("report", report, ("vehicle_kind",), "glider", rep_cmd, "is a auv", "analysed vehicle")
    bad = dict(report, recommendation={"points": [{"name": "aft_upper", "add_kg": 0.1}]})
    write("report_foreign_points.json", json.dumps(bad, indent=2))
    case("report_foreign_points", rep_cmd.format(f="{bad}/report_foreign_points.json"), "report_foreign_points.json",
         "recommendation.points[0].name", "not an adjustment point of 'hugin1000'")
    value_variant("report", report, ("net_buoyancy_sigma_kg",), -1, rep_cmd, "net_buoyancy_sigma_kg", "must be >= 0")

    # ---- command-line numbers ----
    fm = ("first-mission --vehicle hugin1000 --scales 392.3,391.3,391.3,390.3 --total 1565.2 --rope-x 1.3422,-1.6578 "
          "--temperature 6.5 --salinity 34.5")
    case("cli_installed_300000", fm + " --installed 300000,0,0,0", "installed", "capacity", "check the value")
    case("cli_installed_1e308", fm + " --installed 1e308,0,0,0", "installed", "capacity")
    case("cli_installed_over_capacity", fm + " --installed 43.2,14.4,19.2,19.2", "installed", "capacity 40 kg")
    case("cli_installed_negative", fm + " --installed -1,0,0,0", "installed", "0 or more")
    case("cli_installed_nan", fm + " --installed nan,0,0,0", "installed")
    case("cli_installed_count", fm + " --installed 1,2", "installed")
    case("cli_temperature_1e308", fm.replace("--temperature 6.5", "--temperature 1e308"), "temperature")
    case("cli_salinity_negative", fm.replace("--salinity 34.5", "--salinity -5"), "salinity")
    case("cli_depth_negative", fm + " --depth -10", "depth")
    case("cli_depth_huge", fm + " --depth 1e9", "depth")
    case("cli_latitude", fm + " --latitude 400", "latitude")
    case("cli_total_zero", fm.replace("--total 1565.2", "--total 0"), "total")
    case("cli_scales_text", fm.replace("--scales 392.3,391.3,391.3,390.3", "--scales a,b,c,d"), "scales")
    case("cli_policy", fm + " --policy greedy", "policy", "exact")
    case("cli_density_salinity", "density --salinity -1 --temperature 10", "salinity")
    case("cli_density_temperature", "density --salinity 35 --temperature 1e999", "temperature")
    case("cli_density_pressure", "density --salinity 35 --temperature 10 --pressure 1e308", "pressure")
    case("cli_plan_installed_300000", rep_cmd.format(f="{res}/../tests/data/bad/report_ok.json")
         .replace("7.2,7.2,25.2,25.2", "300000,0,0,0"), "installed", "capacity")
    write("report_ok.json", json.dumps(report, indent=2))
    case("cli_plan_accept_unknown_config",
         "plan --vehicle hugin1000 --config 9-9-9 --report {bad}/report_ok.json --installed 7.2,7.2,25.2,25.2 "
         "--temperature 8 --salinity 35 --depth 50 --accept --history {tmp}/accept.sqlite", "9-9-9",
         "not in the history", "first-mission", "--config 9-9-9", "--history")
    case("cli_first_mission_history_without_config", fm + " --history {tmp}/h.sqlite", "history", "--config")
    case("cli_first_mission_bad_config", fm + " --config 1-2 --history {tmp}/h.sqlite", "config")

    # ---- mission logs ----
    an = "analyze --vehicle hugin1000 --log {f}"
    rows = "".join("%d,%.1f,%.2f,0.1,1.5,120\n" % (t, 50.0, 0.5) for t in range(40))
    write("log_no_time_column.csv", "depth [m],pitch [deg]\n" + "".join("%.1f,0.5\n" % (i,) for i in range(20)))
    case("log_no_time_column", an.format(f="{bad}/log_no_time_column.csv"), "log_no_time_column.csv:1:",
         "no `time` column", "time [s]")
    write("log_equal_times.csv", "time [s],depth [m],pitch [deg]\n" + "".join("5,%d,0.5\n" % i for i in range(30)))
    case("log_equal_times", an.format(f="{bad}/log_equal_times.csv"), "log_equal_times.csv:3:",
         "all 30 rows have the same time", "increase strictly")
    write("log_backwards_times.csv",
          "time [s],depth [m],pitch [deg]\n" + "".join("%d,%d,0.5\n" % (100 - i, i) for i in range(30)))
    case("log_backwards_times", an.format(f="{bad}/log_backwards_times.csv"), "log_backwards_times.csv:3:",
         "go backwards", "increase strictly")
    hdr = "time [s],depth [m],pitch [%s],roll [%s],speed [m/s],prop_rpm [rpm]\n"
    import math
    deg_rows = "".join("%d,%.2f,%.3f,%.3f,1.5,120\n" % (t, 20 + 30 * math.sin(t / 50.0), 5 + 10 * math.sin(t / 20.0),
                                                        3 + math.cos(t / 7.0), ) for t in range(400))
    write("log_degrees_under_rad.csv", "# vehicle: hugin1000\n" + hdr % ("rad", "rad") + deg_rows)
    case("log_degrees_under_rad", an.format(f="{bad}/log_degrees_under_rad.csv"), "log_degrees_under_rad.csv:2:",
         "pitch", "beyond +-90 deg", "pitch [deg]")
    write("log_roll_degrees_under_rad.csv", "# vehicle: hugin1000\n" + hdr % ("deg", "rad") +
          "".join("%d,%.2f,%.3f,%.3f,1.5,120\n" % (t, 20 + 30 * math.sin(t / 50.0), 2.0, 20 + 30 * math.sin(t / 9.0))
                  for t in range(400)))
    case("log_roll_degrees_under_rad", an.format(f="{bad}/log_roll_degrees_under_rad.csv"),
         "log_roll_degrees_under_rad.csv:2:", "roll", "beyond +-180 deg", "roll [deg]")
    write("log_empty.csv", "")
    case("log_empty", an.format(f="{bad}/log_empty.csv"), "log_empty.csv")
    write("log_header_only.csv", "time [s],depth [m]\n")
    case("log_header_only", an.format(f="{bad}/log_header_only.csv"), "log_header_only.csv", "rows")
    write("log_metadata_only.csv", "# vehicle: hugin1000\n# start: 2026-05-14T08:12:00Z\n")
    case("log_metadata_only", an.format(f="{bad}/log_metadata_only.csv"), "log_metadata_only.csv")
    write_bytes("log_utf16.csv", "time [s],depth [m]\n0,1\n".encode("utf-16"))
    case("log_utf16", an.format(f="{bad}/log_utf16.csv"), "log_utf16.csv")
    write_bytes("log_binary_garbage.csv", bytes((i * 7919) % 256 for i in range(65536)))
    case("log_binary_garbage", an.format(f="{bad}/log_binary_garbage.csv"), "log_binary_garbage.csv")
    write("log_long_header.csv", "time [s]," + ",".join("c%d [m]" % i for i in range(40000)) + "\n0," +
          ",".join("1" for _ in range(40000)) + "\n")
    case("log_long_header", an.format(f="{bad}/log_long_header.csv"), "log_long_header.csv")
    write("log_long_line.csv", "time [s],depth [m]\n" + "0," + "9" * 1200000 + "\n1,2\n")
    case("log_long_line", an.format(f="{bad}/log_long_line.csv"), "log_long_line.csv")
    write("log_unit_unknown.csv", "time [s],depth [furlong]\n0,1\n1,2\n")
    case("log_unit_unknown", an.format(f="{bad}/log_unit_unknown.csv"), "log_unit_unknown.csv", "furlong")
    write("log_time_unit_wrong.csv", "time [m],depth [m]\n0,1\n1,2\n")
    case("log_time_unit_wrong", an.format(f="{bad}/log_time_unit_wrong.csv"), "log_time_unit_wrong.csv",
         "not a time unit")
    write("log_1e999_cells.csv", "time [s],depth [m],pitch [deg]\n" + "".join("%d,1e999,1e999\n" % t for t in range(50)))
    case("log_1e999_cells", an.format(f="{bad}/log_1e999_cells.csv"), "log_1e999_cells.csv")
    # Raw Slocum binaries: the ASCII path must not tell to re-export with m_present_time.
    write_bytes("unit_123.dbd", b"dbd_label:    DBD(dinkum_binary_data)file\nencoding_ver:    5\n" +
                bytes((i * 31) % 256 for i in range(4096)))
    case("log_slocum_dbd", an.format(f="{bad}/unit_123.dbd"), "unit_123.dbd:3:1", "not a complete Slocum binary file", "copy it from the glider again")
    write_bytes("unit_123.sbd", b"dbd_label:    DBD(dinkum_binary_data)file\nencoding_ver:    5\n" +
                bytes((i * 37) % 256 for i in range(4096)))
    case("log_slocum_sbd", an.format(f="{bad}/unit_123.sbd"), "unit_123.sbd:3:1", "not a complete Slocum binary file", "copy it from the glider again")
    case("log_fifo", an.format(f="{fifo}"), "FIFO", "regular file")
    case("log_device", an.format(f="/dev/zero"), "/dev/zero", "device", "regular file")
    case("log_missing", an.format(f="{bad}/no_such_log.csv"), "no_such_log.csv", "cannot open")
    case("replay_fifo", "simulate --vehicle hugin1000 --replay {fifo} --out {tmp}/r.csv", "FIFO")
    case("model_check_fifo", "model-check --vehicle hugin1000 --log {fifo}", "FIFO")
    case("convert_device", "convert --log /dev/zero --out {tmp}/c.csv", "/dev/zero", "device")

    # ---- history files ----
    write("history_not_sqlite.sqlite", "this is not a database\n" * 100)
    case("history_not_sqlite", "history --config 1-2-3 --history {bad}/history_not_sqlite.sqlite",
         "history_not_sqlite.sqlite", "not a SQLite database")
    case("history_is_folder", "history --config 1-2-3 --history {bad}", "is a folder", "file name inside it")
    case("history_unknown_config", "history --config 7-7-7 --history {tmp}/empty.sqlite", "7-7-7", "not in the history")

    # A SQLite file with a damaged page (quick_check fails): never written to.
    import sqlite3
    db = os.path.join(OUT, "history_damaged.sqlite")
    con = sqlite3.connect(db)
    con.execute("PRAGMA page_size = 1024")
    con.execute("CREATE TABLE notes (id INTEGER PRIMARY KEY, text TEXT)")
    con.executemany("INSERT INTO notes (text) VALUES (?)", [("note %d " % i * 8,) for i in range(400)])
    con.commit()
    con.close()
    with open(db, "r+b") as f:
        f.seek(1024 * 5)  # a leaf page of the table
        f.write(bytes((i * 13 + 7) % 256 for i in range(1024)))
    case("history_damaged_check", "history --check --history {bad}/history_damaged.sqlite", "history_damaged.sqlite",
         "damaged", "restore")
    case("history_damaged_list", "history --config 1-2-3 --history {bad}/history_damaged.sqlite",
         "history_damaged.sqlite", "damaged", "restore the automatic backup")
    case("history_damaged_first_mission", "first-mission --weighing {res}/examples/hugin1000_first_mission.json "
         "--config 1-2-3 --history {bad}/history_damaged.sqlite", "history_damaged.sqlite", "damaged",
         "restore the automatic backup")

    with open(os.path.join(OUT, "catalogue.tsv"), "w") as f:
        f.write("# name\targuments\texpected fragments of the one-line refusal ('|'-separated); "
                "generated by scripts/make-bad-inputs.py\n")
        for c in cases:
            f.write("\t".join(c) + "\n")
    print("%d cases, %d files in %s" % (len(cases), len(os.listdir(OUT)), OUT))


if __name__ == "__main__":
    main()
