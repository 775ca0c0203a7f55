"""Interactive (plotly) figures of a study's report: a response against each factor, a fitted surface over two
factors, and Sobol' indices as bars.

They draw what :mod:`jointplay.study.plots` draws with matplotlib, from the same pieces (level means from
:func:`~jointplay.study.plots.groups` and :func:`~jointplay.study.plots.group_means`, a factor's real
values at coded -1 and +1 from :func:`~jointplay.study.plots.factor_ends`), so the report and
``jointplay sweep``'s figures agree. Factor values are in SI units, as in the study's Dataset.
"""

from __future__ import annotations

import numpy as np

from ..study.plots import MAIN_EFFECT_BINS, MAX_LEVELS, factor_ends, group_means, groups

#: Grid points along each axis of a surface's contour.
CONTOUR_POINTS = 61


def _label(dataset, name: str) -> str:
    units = str(dataset[name].attrs.get("units", ""))
    return f"{name} [{units}]" if units else name


def _factors(dataset) -> list[str]:
    return [str(f) for f in dataset["factor"].values]


def response_figure(dataset, response: str):
    """(figure, caption): one panel per factor, the response of every finished case against the factor's
    value and the mean over the cases at each level (or bin) of it."""
    import plotly.graph_objects as go
    from plotly.subplots import make_subplots

    factors = _factors(dataset)
    y = np.asarray(dataset[response].values, dtype=float)
    finite = np.isfinite(y)
    figure = make_subplots(rows=1, cols=len(factors), shared_yaxes=True, horizontal_spacing=0.06)
    binned = []
    for j, factor in enumerate(factors, start=1):
        x = np.asarray(dataset[factor].values, dtype=float)
        positions, group, was_binned = groups(x, MAX_LEVELS, MAIN_EFFECT_BINS)
        figure.add_trace(go.Scatter(x=x[finite], y=y[finite], mode="markers", name="cases", showlegend=j == 1,
                                    marker={"color": "#1f77b4", "size": 6}, legendgroup="cases"), row=1, col=j)
        figure.add_trace(go.Scatter(x=positions, y=group_means(y, group, len(positions)), mode="lines+markers",
                                    name="mean at each level" + (" (bins)" if was_binned else ""),
                                    showlegend=j == 1, line={"color": "#d62728"}, legendgroup="means"), row=1, col=j)
        figure.update_xaxes(title_text=_label(dataset, factor), row=1, col=j, **_ticks(dataset, factor, was_binned))
        if was_binned:
            binned.append(factor)
    figure.update_yaxes(title_text=_label(dataset, response), row=1, col=1)
    figure.update_layout(title=f"{_label(dataset, response)} against each factor", height=380)
    caption = f"{response} of every finished case against each factor, and its mean at each level of that factor " \
              "(averaged over the other factors)"
    if binned:
        caption += f"; {', '.join(binned)} binned into {MAIN_EFFECT_BINS} equal-width intervals"
    n_failed = int(np.count_nonzero(~finite))
    return figure, caption + (f"; {n_failed} failed cases left out." if n_failed else ".")


def _ticks(dataset, factor: str, binned: bool) -> dict:
    """A discrete factor's level names (``<factor>_label``) as tick labels."""
    name = f"{factor}_label"
    if binned or name not in dataset.coords:
        return {}
    values, labels = np.asarray(dataset[factor].values, dtype=float), dataset[name].values
    levels = np.unique(values)
    return {"tickvals": list(levels), "ticktext": [str(labels[np.flatnonzero(values == v)[0]]) for v in levels]}


def most_influential(dataset, response: str, indices=None) -> tuple[tuple[str, str], str]:
    """The two factors with the largest total Sobol' indices (when given), else with the widest spread of the
    response's level means; and the reason, in words."""
    factors = _factors(dataset)
    if indices is not None:
        order = np.argsort(-np.asarray(indices.total), kind="stable")
        return (factors[order[0]], factors[order[1]]), "the two factors with the largest total Sobol' indices"
    y = np.asarray(dataset[response].values, dtype=float)
    spreads = []
    for factor in factors:
        positions, group, _ = groups(dataset[factor].values, MAX_LEVELS, MAIN_EFFECT_BINS)
        means = group_means(y, group, len(positions))
        spreads.append(float(np.nanmax(means) - np.nanmin(means)) if np.isfinite(means).any() else 0.0)
    order = np.argsort(-np.asarray(spreads), kind="stable")
    return (factors[order[0]], factors[order[1]]), "the two factors whose level means of the response spread widest"


def contour_figure(surface, dataset, pair: tuple[str, str], reason: str):
    """(figure, caption): the fitted surface over ``pair`` in their real units (coded for a factor whose values
    are not linear in its coded coordinate), every other factor at its centre (coded 0), with the cases."""
    import plotly.graph_objects as go

    names = list(surface.factor_names)
    ends = {n: e for n in names if (e := factor_ends(dataset, n)) is not None}
    grid = np.linspace(-1.0, 1.0, CONTOUR_POINTS)
    c1, c2 = np.meshgrid(grid, grid)
    at = np.zeros((c1.size, len(names)))
    at[:, names.index(pair[0])], at[:, names.index(pair[1])] = c1.ravel(), c2.ravel()
    z = surface.predict(at).reshape(c1.shape)
    x_axis, y_axis = (_real(grid, f, ends) for f in pair)
    coded = np.asarray(dataset["coded"].values, dtype=float)
    response = _label(dataset, surface.response)
    figure = go.Figure(go.Contour(x=x_axis, y=y_axis, z=z, colorscale="Viridis", ncontours=15,
                                  colorbar={"title": {"text": response}}, name="surface"))
    figure.add_trace(go.Scatter(x=_real(coded[:, names.index(pair[0])], pair[0], ends),
                                y=_real(coded[:, names.index(pair[1])], pair[1], ends), mode="markers",
                                marker={"color": "black", "size": 6}, name="cases"))
    figure.update_layout(title=f"{response}: quadratic surface over {pair[0]} and {pair[1]} "
                               f"({surface.verdict}, Q^2 = {surface.q2:.3g})", height=480,
                         xaxis_title=_axis_title(dataset, pair[0], ends),
                         yaxis_title=_axis_title(dataset, pair[1], ends))
    held = [_held_text(dataset, n, ends) for n in names if n not in pair]
    caption = f"The fitted quadratic surface of {surface.response} over {reason} ({pair[0]}, {pair[1]}), " \
              f"with the cases; {surface.verdict_text()}"
    return figure, caption + (f"; held at their centre: {', '.join(held)}." if held else ".")


def _real(coded, factor: str, ends: dict):
    from ..study.designs import uncode

    return uncode(coded, *ends[factor]) if factor in ends else np.asarray(coded, dtype=float)


def _axis_title(dataset, factor: str, ends: dict) -> str:
    return _label(dataset, factor) if factor in ends else f"{factor} (coded, -1 .. +1 over its levels)"


def _held_text(dataset, factor: str, ends: dict) -> str:
    if factor not in ends:
        return f"{factor} = 0 (coded)"
    units = str(dataset[factor].attrs.get("units", ""))
    return f"{factor} = {0.5 * sum(ends[factor]):.4g} {units}".rstrip()


def sensitivity_figure(indices, response: str):
    """First-order and total Sobol' indices of each factor as bars, with their 95 % bootstrap half-widths."""
    import plotly.graph_objects as go

    names = list(indices.factor_names)
    figure = go.Figure([
        go.Bar(x=names, y=indices.first_order, name="first-order S1",
               error_y={"type": "data", "array": indices.first_order_conf}),
        go.Bar(x=names, y=indices.total, name="total ST", error_y={"type": "data", "array": indices.total_conf})])
    figure.update_layout(title=f"Sobol' indices of {response}", barmode="group", height=360,
                         xaxis_title="factor", yaxis_title="share of the variance of "
                                                           f"{response} [-] (0 .. 1)")
    return figure
