"""The sections of a study's report, read from the study's folder alone.

A study folder (:mod:`jointplay.study.store`) holds ``study.json`` (the manifest), ``study.nc`` (the
Dataset with a ``case`` dimension) and, after ``jointplay optimize``, ``optimum.json``. The report shows
what the study's own code computes, never a second calculation: the design table is the Dataset's
values; the response surfaces are :func:`jointplay.study.summary.surfaces`; the sensitivities are
:func:`jointplay.study.sensitivity.sobol_indices`, given for the responses ``jointplay sweep`` gives them
for; the optimum is the file ``jointplay optimize`` wrote, or, without one, the best cases of each
response as ``jointplay sweep`` lists them (:func:`jointplay.study.summary.best_cases`).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from ..errors import ModelError, Problem
from .blocks import Plot, Section, Table, Text

#: The file ``jointplay optimize`` writes into the study's folder.
OPTIMUM = "optimum.json"


def study_sections(folder: str | Path) -> tuple[str, list[Section]]:
    """(title, sections) of the report of the study in ``folder``: its definition, the design table,
    response surfaces, sensitivities, the optimum (or best cases) and the failed cases. A folder that is
    missing or holds no finished study is a ModelError located at the missing file."""
    from ..study.factors import Factor
    from ..study.summary import surfaces

    manifest, dataset, optimum = read_study_folder(folder)
    factors = [Factor(**{**f, "levels": tuple(f["levels"]), "labels": tuple(f["labels"])})
               for f in json.loads(dataset.attrs["factors"])]
    responses = [str(r) for r in manifest["responses"]]
    fitted = surfaces(dataset, responses)
    indices = sensitivities(dataset, fitted)
    sections = [definition_section(manifest, dataset, factors, responses),
                design_section(dataset, factors, responses),
                surfaces_section(dataset, fitted, indices),
                sensitivity_section(dataset, fitted, indices),
                optimum_section(dataset, factors, responses, optimum),
                failures_section(dataset, factors)]
    return f"Study: {manifest.get('study', Path(folder).name)}", sections


# --- the folder ---------------------------------------------------------------------------------------------

def read_study_folder(folder: str | Path) -> tuple[dict, object, dict | None]:
    """(manifest, Dataset, optimum or None) of a study folder; a ModelError names what is missing."""
    from ..study.dataset import open_study
    from ..study.store import DATASET, MANIFEST, StudyStore

    folder = Path(folder)
    if not folder.is_dir():
        raise ModelError([Problem(str(folder), "no such study folder (jointplay sweep -o FOLDER makes one)")])
    manifest = _read_json(folder / MANIFEST, "missing: not a study folder (jointplay sweep writes study.json)")
    path = folder / DATASET
    if not path.is_file():
        done = len(StudyStore(folder).done())
        raise ModelError([Problem(str(path), f"missing: the study has not finished ({done} of "
                                             f"{manifest.get('cases', '?')} cases done); run it again with --resume")])
    try:
        dataset = open_study(path)
    except (OSError, ValueError) as exc:
        raise ModelError([Problem(str(path), f"cannot be read as a study's Dataset ({exc})")]) from None
    missing = [r for r in manifest.get("responses", []) if r not in dataset.data_vars]
    if "factors" not in dataset.attrs or "coded" not in dataset.data_vars or missing:
        raise ModelError([Problem(str(path), "is not the Dataset of the study in study.json (no factors, coded "
                                             f"design or response {', '.join(missing)})")])
    if dataset.sizes["case"] != manifest.get("cases"):
        raise ModelError([Problem(str(path), f"holds {dataset.sizes['case']} cases, study.json says "
                                             f"{manifest.get('cases')}; run the study again with --resume")])
    optimum_path = folder / OPTIMUM
    optimum = _read_json(optimum_path, "") if optimum_path.is_file() else None
    factor_names = {f["name"] for f in json.loads(dataset.attrs["factors"])}
    if optimum is not None and not (isinstance(optimum.get("values"), dict) and "method" in optimum
                                    and factor_names <= set(optimum["values"])):
        raise ModelError([Problem(str(optimum_path), "is not an optimum of this study (jointplay optimize writes "
                                                     "its method and a value of every factor)")])
    return manifest, dataset, optimum


def _read_json(path: Path, missing: str) -> dict:
    if not path.is_file():
        raise ModelError([Problem(str(path), missing)])
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError) as exc:
        raise ModelError([Problem(str(path), f"cannot be read as JSON ({exc})")]) from None
    if not isinstance(data, dict):
        raise ModelError([Problem(str(path), "must hold a JSON object")])
    return data


def units_of(dataset, name: str) -> str:
    """The ``units`` attribute of a Dataset variable or coordinate ("" when it has none)."""
    return str(dataset[name].attrs.get("units", ""))


def header(name: str, units: str) -> str:
    """A column or axis title: "name [units]", or the name alone for a unitless quantity."""
    return f"{name} [{units}]" if units else name


# --- definition and design ------------------------------------------------------------------------------

def definition_section(manifest: dict, dataset, factors, responses: list[str]) -> Section:
    """What the study is: its model, factors with their ranges, design, responses and run options."""
    design = json.loads(dataset.attrs["design"])
    design_text = ", ".join(f"{k} = {v}" for k, v in design.items())
    factor_rows = [[f.name, f.path, _range_text(f), f.units or "-", f.description] for f in factors]
    response_rows = [[r, units_of(dataset, r) or "-", str(dataset[r].attrs.get("definition", ""))]
                     for r in responses]
    run = [f"model: {dataset.attrs['model']}", f"{dataset.sizes['case']} cases, design: {design_text}",
           f"each case simulated to t_end = {float(dataset.attrs['t_end']):.6g} s; random designs seeded with "
           f"{int(dataset.attrs['seed'])}", f"jointplay {dataset.attrs['jointplay_version']}"]
    if "time" in dataset.coords:
        channels = [str(v) for v in dataset.data_vars if dataset[v].dims == ("case", "time")]
        step = float(dataset["time"].values[1] - dataset["time"].values[0]) if dataset.sizes["time"] > 1 else 0.0
        run.append(f"channels kept per case every {step:.6g} s: {', '.join(channels)}")
    return Section("Study definition", [
        Text("; ".join(run) + "."),
        Table(["factor", "--set path", "range or levels", "units (SI)", "description"], factor_rows,
              "Factors varied by their --set paths; values in SI units."),
        Table(["response", "units", "definition"], response_rows, "Responses measured on each run.")])


def _range_text(factor) -> str:
    if factor.discrete:
        return ", ".join(factor.label(v) for v in factor.levels)
    return f"{factor.low:.6g} .. {factor.high:.6g} {factor.units}".strip()


def design_section(dataset, factors, responses: list[str]) -> Section:
    """Every case: its factor values [SI] (a level's name beside a discrete factor), its responses with units,
    its status and the run's accepted steps."""
    columns = ["case"]
    for f in factors:
        columns.append(header(f.name, f.units))
        if f.discrete and f.labels:
            columns.append(f"{f.name} level")
    columns += [header(r, units_of(dataset, r)) for r in responses] + ["status", "steps"]
    rows = []
    for k in range(dataset.sizes["case"]):
        row = [int(dataset["case"].values[k])]
        for f in factors:
            value = float(dataset[f.name].values[k])
            row += [value, f.label(value)] if f.discrete and f.labels else [value]
        row += [float(dataset[r].values[k]) for r in responses]
        row += [str(dataset["status"].values[k]), int(dataset["steps"].values[k])]
        rows.append(row)
    return Section("Design table", [Table(columns, rows, "Every case of the design with its responses "
                                                         "(NaN where the case failed).")])


# --- surfaces and sensitivities -------------------------------------------------------------------------------

def sensitivities(dataset, fitted: dict) -> dict:
    """Sobol' indices of each response ``jointplay sweep`` gives them for (from the cases of a Saltelli design
    where every case finished, else from a trustworthy surface), by response."""
    from ..study.sensitivity import saltelli_base_samples, sobol_indices

    saltelli = saltelli_base_samples(dataset["coded"].values) is not None
    found = {}
    for response, surface in fitted.items():
        trusted = not isinstance(surface, str) and surface.verdict == "trustworthy"
        if trusted or (saltelli and bool(dataset[response].notnull().all())):
            found[response] = sobol_indices(dataset, response)
    return found


def surfaces_section(dataset, fitted: dict, indices: dict) -> Section:
    """Each response against each factor (cases and level means), the quality of its quadratic surface, and
    the surface over its two most influential factors."""
    from .study_plots import contour_figure, most_influential, response_figure

    blocks = [Table(["response", "cases", "terms", "R^2", "adjusted R^2", "Q^2 (leave-one-out)", "verdict"],
                    [_quality_row(r, s) for r, s in fitted.items()],
                    "Quadratic response surfaces in coded factors, fitted by least squares; trustworthy when "
                    "Q^2 >= 0.5 and adjusted R^2 >= 0.8.")]
    for response, surface in fitted.items():
        figure, caption = response_figure(dataset, response)
        blocks.append(Plot(figure, caption))
        if isinstance(surface, str) or len(surface.factor_names) < 2:
            continue
        pair, reason = most_influential(dataset, response, indices.get(response))
        figure, caption = contour_figure(surface, dataset, pair, reason)
        blocks.append(Plot(figure, caption))
    return Section("Response surfaces", blocks)


def _quality_row(response: str, surface) -> list:
    if isinstance(surface, str):
        return [response, "-", "-", "-", "-", "-", f"not fitted: {surface}"]
    q = surface.quality()
    return [response, q["cases"], q["terms"], q["r2"], q["r2_adjusted"], q["q2"], q["verdict_text"]]


def sensitivity_section(dataset, fitted: dict, indices: dict) -> Section:
    """Sobol' indices as a bar chart and a table, each response with the method that gave them."""
    from .study_plots import sensitivity_figure

    blocks = []
    for response in fitted:
        found = indices.get(response)
        if found is None:
            blocks.append(Text(f"{response}: no sensitivity indices; the design is not a Saltelli sample with every "
                               "case finished, and the response's quadratic surface is not trustworthy."))
            continue
        method = sensitivity_method(found)
        rows = [[name, float(found.first_order[j]), float(found.first_order_conf[j]), float(found.total[j]),
                 float(found.total_conf[j])] for j, name in enumerate(found.factor_names)]
        blocks.append(Plot(sensitivity_figure(found, response), f"{response}: {method}"))
        blocks.append(Table(["factor", "first-order S1", "S1 95 % half-width", "total ST", "ST 95 % half-width"],
                            rows, f"Sobol' indices of {response} (unitless shares of its variance): {method}"))
    return Section("Sensitivities", blocks)


def sensitivity_method(found) -> str:
    """How a set of Sobol' indices was estimated, in one sentence."""
    if found.source == "design":
        where = f"from the study's cases (a Saltelli design, N = {found.n_base} base samples)"
    else:
        where = (f"from the fitted quadratic surface evaluated on a Saltelli sample of N = {found.n_base} base "
                 f"samples of the factors' ranges {found.note.removeprefix('on the fitted surface ')}")
    return f"Sobol' indices by SALib {where}; 95 % bootstrap half-widths."


# --- optimum and failures ----------------------------------------------------------------------------------------

def optimum_section(dataset, factors, responses: list[str], optimum: dict | None) -> Section:
    """The optimum ``jointplay optimize`` found and verified, or the best cases of each response."""
    if optimum is not None:
        return Section("Optimum", [
            Text(f"Found by {optimum['method']} (weighted objective {_number(optimum.get('objective'))}); "
                 + ("run once more: the surfaces' prediction beside the run." if optimum.get("predicted") else
                    "the best run of the search, so no surface prediction.")),
            Table(["factor", "value"], [[f.name, _optimum_label(f, optimum)] for f in factors],
                  "Factor values at the optimum."),
            Table(["response", "predicted (surface)", "run", "difference [%]"],
                  [_verified_row(r, units_of(dataset, r), optimum) for r in responses],
                  "Responses at the optimum: predicted by the quadratic surfaces and from the verifying run.")])
    from ..study.summary import best_cases

    blocks = [Text("The study holds no optimisation (jointplay optimize writes optimum.json); its best cases "
                   "for each response, smallest first, as jointplay sweep lists them.")]
    for response in responses:
        rows = [[k, *[f.label(float(dataset[f.name].values[k])) for f in factors], float(dataset[response].values[k])]
                for k in best_cases(dataset, response)]
        blocks.append(Table(["case", *[f.name for f in factors], header(response, units_of(dataset, response))],
                            rows, f"Cases with the smallest {response}."))
    return Section("Best cases", blocks)


def _optimum_label(factor, optimum: dict) -> str:
    """A factor's value at the optimum as ``jointplay optimize`` named it (a level, an ISO grade), else in SI."""
    return optimum.get("labels", {}).get(factor.name) or factor.label(float(optimum["values"][factor.name]))


def _verified_row(response: str, units: str, optimum: dict) -> list:
    predicted = optimum.get("predicted", {}).get(response, math.nan)
    run = optimum.get("verified", {}).get(response, math.nan)
    difference = 100.0 * (run - predicted) / abs(run) if run and math.isfinite(predicted) else math.nan
    return [header(response, units), predicted, run, difference]


def _number(value) -> str:
    return "-" if value is None or not math.isfinite(float(value)) else f"{float(value):.4g}"


def failures_section(dataset, factors) -> Section:
    """Every failed case with its factor values and its error."""
    from ..study.summary import failures

    failed = failures(dataset)
    if not failed:
        return Section("Failed cases", [Text(f"None: all {dataset.sizes['case']} cases finished.")])
    rows = [[k, *[f.label(float(dataset[f.name].values[k])) for f in factors], error] for k, error in failed]
    return Section("Failed cases", [Table(["case", *[f.name for f in factors], "error"], rows,
                                          f"{len(failed)} of {dataset.sizes['case']} cases failed; their responses "
                                          "are NaN and left out of the surfaces.")])


__all__ = ["read_study_folder", "study_sections"]
