// resect-plot: the plots of `resect bench` (README, "What accuracy costs in time"), drawn
// with VTK's charts into PNG files:
//   cost_MESH.png   accuracy (max sweep error) against cost: the cut (+ embedded surface) time
//                   and the simulation time per simulated second, all variants of each method
//                   as points and each method's Pareto front as a line;
//   d_MESH.png      against d: sweep error, minimum radius ratio, stable time step;
//   scaling.png     log-log: absolute times and per-unit costs against the mesh size, with
//                   the targets as dashed lines;
//   resection.png   `resect bench resection`: worst radius ratio, shortest edge (both log) and
//                   tets of the remaining tissue, over the input's, against the pass; one line
//                   per mesh (line and marker style) and method (colour);
//   realtime.png    `resect bench realtime`: log-log, the real-time factor against tets per
//                   integrator and step (lines through the boxes, dots for the samples) with a
//                   line at 1x, and the projective-dynamics factorisation costs.
//
//   resect-plot [--accuracy accuracy_time.csv] [--scaling scaling.csv]
//               [--resection resection.csv] [--realtime realtime.csv] --out DIR
//
// VTK 9.1 on Debian renders through GLX, so this needs an X display (run it under
// `xvfb-run -a` on a headless machine; `resect bench` does). It checks the display and GLX
// before VTK touches them, so that it fails with a message instead of aborting.
// Exit codes: 0 written; 2 bad input (a missing or malformed CSV); 1 cannot render (no
// display, no GLX, a blank image, a write failure).
#include "app/plot/display_check.h"
#include "scenario/atomic_file.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <string>
#include <vector>

namespace {

struct Failure {
    int code;
    std::string message;
};

// ---------------------------------------------------------------- CSV

/// A CSV file with a header line; cells by column name.
class Csv {
public:
    static Csv read(const std::string& path) {
        std::ifstream f(path);
        if (!f)
            throw Failure{2, path + ": cannot read"};
        Csv csv;
        csv.m_path = path;
        std::string line;
        if (!std::getline(f, line))
            throw Failure{2, path + ": empty"};
        const std::vector<std::string> header = split(line);
        for (std::size_t i = 0; i < header.size(); ++i)
            csv.m_columns[header[i]] = i;
        while (std::getline(f, line)) {
            if (line.empty())
                continue;
            std::vector<std::string> cells = split(line);
            if (cells.size() != header.size())
                throw Failure{2, path + ": a row has " + std::to_string(cells.size()) + " cells, the header " +
                                     std::to_string(header.size())};
            csv.m_rows.push_back(std::move(cells));
        }
        return csv;
    }
    int rows() const { return static_cast<int>(m_rows.size()); }
    const std::string& text(int row, const std::string& column) const { return m_rows[row][index(column)]; }
    double number(int row, const std::string& column) const {
        const std::string& s = text(row, column);
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str())
            throw Failure{2, m_path + ": column " + column + ": not a number: '" + s + "'"};
        return v;
    }

private:
    static std::vector<std::string> split(const std::string& line) {
        std::vector<std::string> out;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ','))
            out.push_back(cell);
        if (!line.empty() && line.back() == ',')
            out.emplace_back(); // a trailing empty cell (getline does not return it)
        return out;
    }
    std::size_t index(const std::string& column) const {
        auto it = m_columns.find(column);
        if (it == m_columns.end())
            throw Failure{2, m_path + ": no column '" + column + "'"};
        return it->second;
    }
    std::string m_path;
    std::map<std::string, std::size_t> m_columns;
    std::vector<std::vector<std::string>> m_rows;
};

// ---------------------------------------------------------------- charts

struct Rgb {
    unsigned char r, g, b;
};

/// x, y pairs of one series.
using Points = std::vector<std::pair<double, double>>;

enum class Style { Line, Markers, LineAndMarkers, Dashed };

/// The plot added, or null if no point can be shown.
vtkPlot* addSeries(vtkChart* chart, const std::string& label, Points points, Rgb colour,
                   Style style, bool logX, bool logY, bool sortByX = true) {
    // Log axes cannot show zero or negative values: leave those points out.
    std::erase_if(points, [&](const auto& p) {
        return !std::isfinite(p.first) || !std::isfinite(p.second) || (logX && p.first <= 0) ||
               (logY && p.second <= 0);
    });
    if (points.empty())
        return nullptr;
    if (sortByX)
        std::sort(points.begin(), points.end());
    if (points.size() < 2 && style != Style::Markers)
        style = Style::LineAndMarkers;  // one point: drawn as a marker (a line needs two)
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> xs, ys;
    xs->SetName("x");
    ys->SetName(label.c_str());
    table->AddColumn(xs);
    table->AddColumn(ys);
    table->SetNumberOfRows(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        table->SetValue(static_cast<vtkIdType>(i), 0, points[i].first);
        table->SetValue(static_cast<vtkIdType>(i), 1, points[i].second);
    }
    const bool line = style != Style::Markers && points.size() >= 2;
    vtkPlot* plot = chart->AddPlot(line ? vtkChart::LINE : vtkChart::POINTS);
    plot->SetInputData(table, 0, 1);
    plot->SetLabel(label);
    plot->SetColor(colour.r, colour.g, colour.b, 255);
    plot->SetWidth(style == Style::Markers ? 1.0f : 2.5f);
    if (style == Style::Dashed)
        plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
    if (auto* p = vtkPlotPoints::SafeDownCast(plot)) {
        if (style == Style::Line || style == Style::Dashed)
            p->SetMarkerStyle(vtkPlotPoints::NONE);
        else {
            p->SetMarkerStyle(vtkPlotPoints::CIRCLE);
            p->SetMarkerSize(style == Style::Markers ? 6.0f : 8.0f);
        }
    }
    if (style == Style::Markers)
        plot->SetColor(colour.r, colour.g, colour.b, 110);
    return plot;
}

void setupChart(vtkChart* chart, const std::string& title, const std::string& xTitle, const std::string& yTitle,
                bool logX, bool logY) {
    chart->SetTitle(title);
    chart->GetTitleProperties()->SetFontSize(15);
    chart->SetShowLegend(true);
    auto* xy = vtkChartXY::SafeDownCast(chart);
    for (auto [axis, text, log] : {std::tuple{vtkAxis::BOTTOM, xTitle, logX}, std::tuple{vtkAxis::LEFT, yTitle, logY}}) {
        vtkAxis* a = chart->GetAxis(axis);
        a->SetTitle(text);
        a->GetTitleProperties()->SetFontSize(13);
        a->GetLabelProperties()->SetFontSize(11);
        a->SetLogScale(log);
    }
    if (xy)
        xy->GetLegend()->GetLabelProperties()->SetFontSize(11);
}

/// Renders the view and writes a PNG atomically; fails if the image is blank.
void writePng(vtkContextView* view, const std::string& path) {
    view->GetRenderWindow()->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view->GetRenderWindow());
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    auto* scalars = vtkUnsignedCharArray::SafeDownCast(image ? image->GetPointData()->GetScalars() : nullptr);
    if (!scalars || scalars->GetNumberOfTuples() == 0)
        throw Failure{1, path + ": rendering gave no image"};
    std::set<unsigned> colours;
    const int comps = scalars->GetNumberOfComponents();
    for (vtkIdType i = 0; i < scalars->GetNumberOfTuples() && colours.size() < 64; i += 7) {
        unsigned c = 0;
        for (int k = 0; k < std::min(comps, 3); ++k)
            c = (c << 8) | scalars->GetValue(i * comps + k);
        colours.insert(c);
    }
    if (colours.size() < 16)
        throw Failure{1, path + ": the rendered image is blank (" + std::to_string(colours.size()) +
                             " colours): no working OpenGL?"};
    const resect::Status s = resect::writeAtomically(path, [&](const std::string& tmp) {
        vtkNew<vtkPNGWriter> writer;
        writer->SetFileName(tmp.c_str());
        writer->SetInputConnection(grab->GetOutputPort());
        writer->Write();
        std::ifstream check(tmp, std::ios::binary | std::ios::ate);
        return check && check.tellg() > 0 ? resect::Status::success() : resect::Status::error(tmp + ": not written");
    });
    if (!s.ok())
        throw Failure{1, s.message()};
    std::printf("resect-plot: wrote %s\n", path.c_str());
}

struct Panels {
    vtkNew<vtkContextView> view;
    vtkNew<vtkChartMatrix> matrix;
    Panels(int columns, int width, int height) {
        view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
        view->GetRenderWindow()->SetSize(width, height);
        view->GetRenderWindow()->SetOffScreenRendering(1);
        view->GetRenderWindow()->SetMultiSamples(0);
        // No interactor: rendering a window with one initialises it on the X display, which
        // crashed in XSync about one run in four under Xvfb (vtkXRenderWindowInteractor).
        view->SetInteractor(nullptr);
        view->GetRenderWindow()->SetInteractor(nullptr);
        matrix->SetSize(vtkVector2i(columns, 1));
        matrix->SetGutter(vtkVector2f(70.0f, 60.0f));
        view->GetScene()->AddItem(matrix);
    }
    vtkChart* chart(int column) { return matrix->GetChart(vtkVector2i(column, 0)); }
};

const Rgb kSubdivision{214, 39, 40}, kStandard{255, 127, 14}, kEnhanced{31, 119, 180};
const Rgb kSnap{44, 160, 44}, kRelax{148, 103, 189}, kRelaxMore{140, 86, 75};

Rgb methodColour(const std::string& method) {
    return method == "subdivision" ? kSubdivision : method == "hybrid-standard" ? kStandard : kEnhanced;
}

/// Lower-left Pareto front of (cost, error): sorted by cost, each point more accurate than
/// every cheaper one.
Points paretoFront(Points points) {
    std::sort(points.begin(), points.end());
    Points front;
    double best = INFINITY;
    for (const auto& p : points)
        if (p.second < best - 1e-12) {
            front.push_back(p);
            best = p.second;
        }
    return front;
}

void plotCost(const Csv& csv, const std::string& mesh, const std::string& dir) {
    Panels panels(2, 1400, 560);
    const struct {
        const char* column;
        const char* title;
    } costs[] = {{"total_ms", "cut + embedded-surface time (ms, median)"},
                 {"sim_ms_per_second", "simulation: compute ms per simulated second"}};
    for (int c = 0; c < 2; ++c) {
        vtkChart* chart = panels.chart(c);
        setupChart(chart, mesh + ": accuracy against " + (c == 0 ? "cut cost" : "simulation cost"), costs[c].title,
                   "max distance of cut faces to the sweep (mean edges)", true, false);
        for (const char* method : {"subdivision", "hybrid-standard", "hybrid-enhanced"}) {
            Points all;
            for (int r = 0; r < csv.rows(); ++r)
                if (csv.text(r, "mesh") == mesh && csv.text(r, "method") == method)
                    all.emplace_back(csv.number(r, costs[c].column), csv.number(r, "sweep_error_max"));
            if (all.empty())
                continue;
            addSeries(chart, std::string(method) + " (all variants)", all, methodColour(method), Style::Markers, true,
                      false, false);
            addSeries(chart, std::string(method) + " Pareto front", paretoFront(all), methodColour(method),
                      Style::LineAndMarkers, true, false);
        }
    }
    writePng(panels.view, dir + "/cost_" + mesh + ".png");
}

void plotD(const Csv& csv, const std::string& mesh, const std::string& dir) {
    int maxRelax = 0;
    for (int r = 0; r < csv.rows(); ++r)
        maxRelax = std::max(maxRelax, static_cast<int>(csv.number(r, "relax_steps")));
    struct Series {
        std::string label, method;
        int snap, relax;
        Rgb colour;
    };
    std::vector<Series> series{{"subdivision", "subdivision", 0, 0, kSubdivision},
                               {"hybrid-standard", "hybrid-standard", 0, 0, kStandard},
                               {"hybrid-enhanced", "hybrid-enhanced", 0, 0, kEnhanced},
                               {"enhanced + snap", "hybrid-enhanced", 1, 0, kSnap},
                               {"enhanced + snap + relax 10", "hybrid-enhanced", 1, 10, kRelax}};
    if (maxRelax > 10)
        series.push_back({"enhanced + snap + relax " + std::to_string(maxRelax), "hybrid-enhanced", 1, maxRelax,
                          kRelaxMore});
    const struct {
        const char* column;
        const char* title;
        bool logY;
    } panelsOf[] = {{"sweep_error_max", "max distance of cut faces to the sweep (mean edges)", false},
                    {"min_radius_ratio", "minimum radius ratio 3r/R after the cut", false},
                    {"stable_dt", "stable explicit time step (s)", true}};
    Panels panels(3, 1800, 560);
    for (int c = 0; c < 3; ++c) {
        vtkChart* chart = panels.chart(c);
        setupChart(chart, mesh + ": " + panelsOf[c].title, "d (fraction of the mean edge length)", panelsOf[c].title,
                   false, panelsOf[c].logY);
        for (const Series& s : series) {
            Points points;
            for (int r = 0; r < csv.rows(); ++r)
                if (csv.text(r, "mesh") == mesh && csv.text(r, "method") == s.method &&
                    static_cast<int>(csv.number(r, "snap")) == s.snap &&
                    static_cast<int>(csv.number(r, "relax_steps")) == s.relax)
                    points.emplace_back(csv.number(r, "d"), csv.number(r, panelsOf[c].column));
            addSeries(chart, s.label, points, s.colour, Style::LineAndMarkers, false, panelsOf[c].logY);
        }
    }
    writePng(panels.view, dir + "/d_" + mesh + ".png");
}

void plotScaling(const Csv& csv, const std::string& dir) {
    Panels panels(2, 1400, 560);
    const auto series = [&](auto value) {
        Points p;
        for (int r = 0; r < csv.rows(); ++r)
            p.emplace_back(csv.number(r, "mesh_tets"), value(r));
        return p;
    };
    vtkChart* absolute = panels.chart(0);
    setupChart(absolute, "Time against mesh size (log-log)", "mesh tets", "ms", true, true);
    addSeries(absolute, "local cut (median)", series([&](int r) { return csv.number(r, "cut_ms"); }), kEnhanced,
              Style::LineAndMarkers, true, true);
    addSeries(absolute, "explicit step, 1 thread",
              series([&](int r) { return 1e-6 * csv.number(r, "step_ns_per_tet_1t") * csv.number(r, "mesh_tets"); }),
              kSubdivision, Style::LineAndMarkers, true, true);
    addSeries(absolute, "explicit step, 2 threads",
              series([&](int r) { return 1e-6 * csv.number(r, "step_ns_per_tet_2t") * csv.number(r, "mesh_tets"); }),
              kStandard, Style::LineAndMarkers, true, true);
    addSeries(absolute, "surface update", series([&](int r) { return csv.number(r, "surface_update_ms"); }), kSnap,
              Style::LineAndMarkers, true, true);

    vtkChart* unit = panels.chart(1);
    setupChart(unit, "Cost per unit of work (log-log; dashed: targets)", "mesh tets",
               "us per touched tet / ns per tet / ns per vertex", true, true);
    addSeries(unit, "cut: us per touched tet", series([&](int r) { return csv.number(r, "us_per_touched_tet"); }),
              kEnhanced, Style::LineAndMarkers, true, true);
    addSeries(unit, "step: ns per tet, 1 thread", series([&](int r) { return csv.number(r, "step_ns_per_tet_1t"); }),
              kSubdivision, Style::LineAndMarkers, true, true);
    addSeries(unit, "step: ns per tet, 2 threads", series([&](int r) { return csv.number(r, "step_ns_per_tet_2t"); }),
              kStandard, Style::LineAndMarkers, true, true);
    addSeries(unit, "surface: ns per vertex", series([&](int r) { return csv.number(r, "surface_ns_per_vertex"); }),
              kSnap, Style::LineAndMarkers, true, true);
    const auto level = [&](double v) { return series([&](int) { return v; }); };
    addSeries(unit, "target: 10 us per touched tet, 10 ns per tet", level(10.0), Rgb{80, 80, 80}, Style::Dashed,
              true, true);
    addSeries(unit, "target: 2 ns per vertex", level(2.0), kSnap, Style::Dashed, true, true);
    writePng(panels.view, dir + "/scaling.png");
}

void plotResection(const Csv& csv, const std::string& dir) {
    std::vector<std::string> meshes, methods;
    for (int r = 0; r < csv.rows(); ++r)
        for (auto [list, column] : {std::pair{&meshes, "mesh"}, std::pair{&methods, "method"}})
            if (std::find(list->begin(), list->end(), csv.text(r, column)) == list->end())
                list->push_back(csv.text(r, column));
    const auto colour = [](const std::string& method) {
        return method == "subdivision" ? kSubdivision : method == "hybrid" ? kStandard : kEnhanced;
    };
    // Meshes told apart by line type and marker (the methods by colour).
    const int lineTypes[] = {vtkPen::SOLID_LINE, vtkPen::DASH_LINE, vtkPen::DOT_LINE,
                             vtkPen::DASH_DOT_LINE, vtkPen::DASH_DOT_DOT_LINE};
    const int markers[] = {vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
                           vtkPlotPoints::CROSS, vtkPlotPoints::PLUS};
    // The legend where the lines rarely are: below, left in the falling ratios (the worst
    // method falls fast), above, left in the tets (which grow, if at all, late).
    const struct {
        const char* column;
        const char* title;
        const char* axis;
        bool logY;
        int legendAt;
    } panelsOf[] = {
        {"worst_ratio_rel", "worst radius ratio over the input's (log)", "worst ratio / input",
         true, vtkChartLegend::BOTTOM},
        {"shortest_edge_rel", "shortest edge over the input's (log)", "shortest edge / input", true,
         vtkChartLegend::BOTTOM},
        {"tets_rel", "tets over the input's", "tets / input", false, vtkChartLegend::TOP}};
    Panels panels(3, 1800, 600);
    for (int c = 0; c < 3; ++c) {
        vtkChart* chart = panels.chart(c);
        setupChart(chart, std::string("Resection: ") + panelsOf[c].title, "pass (scoops so far)",
                   panelsOf[c].axis, false, panelsOf[c].logY);
        if (auto* xy = vtkChartXY::SafeDownCast(chart)) {
            xy->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
            xy->GetLegend()->SetVerticalAlignment(panelsOf[c].legendAt);
        }
        for (std::size_t m = 0; m < meshes.size(); ++m)
            for (const std::string& method : methods) {
                Points points{{0.0, 1.0}}; // pass 0: the input, over itself
                for (int r = 0; r < csv.rows(); ++r)
                    if (csv.text(r, "mesh") == meshes[m] && csv.text(r, "method") == method &&
                        csv.text(r, "status") == "ok")
                        points.emplace_back(csv.number(r, "pass"),
                                            csv.number(r, panelsOf[c].column));
                vtkPlot* plot = addSeries(chart, meshes[m] + ": " + method, points, colour(method),
                                          Style::LineAndMarkers, false, panelsOf[c].logY);
                if (!plot)
                    continue;
                plot->GetPen()->SetLineType(lineTypes[m % std::size(lineTypes)]);
                if (auto* p = vtkPlotPoints::SafeDownCast(plot)) {
                    p->SetMarkerStyle(markers[m % std::size(markers)]);
                    p->SetMarkerSize(6.0f);
                }
            }
    }
    writePng(panels.view, dir + "/resection.png");
}

/// The colour of an integrator (and iteration count) in realtime.png.
Rgb integratorColour(const std::string& integrator, const std::string& iterations) {
    if (integrator == "projective-dynamics")
        return iterations == "1" ? kSnap : iterations == "5" ? kEnhanced : kRelax;
    return integrator == "backward-euler" ? kSubdivision : kStandard;
}

/// "1 ms", "1/60 s" or the step in s (the CSV holds six significant digits).
std::string stepText(double dt) {
    if (std::abs(dt - 0.001) < 1e-5 * dt)
        return "1 ms";
    if (std::abs(dt - 1.0 / 60) < 1e-5 * dt)
        return "1/60 s";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g s", dt);
    return buf;
}

/// Adds a series per key of `rows` (x = tets): a line through the boxes (mesh box-*) and, in the
/// same colour and line type but without a legend entry, dots for the other meshes.
void addBoxesAndSamples(vtkChart* chart, const std::string& label, const Points& boxes,
                        const Points& others, Rgb colour, bool dashed) {
    if (vtkPlot* line = addSeries(chart, label, boxes, colour, Style::LineAndMarkers, true, true))
        if (dashed)
            line->GetPen()->SetLineType(vtkPen::DASH_LINE);
    if (vtkPlot* dots = addSeries(chart, label + " (samples)", others, colour, Style::Markers, true, true,
                                  false)) {
        dots->SetLegendVisibility(boxes.empty());
        if (auto* p = vtkPlotPoints::SafeDownCast(dots))
            p->SetMarkerStyle(dashed ? vtkPlotPoints::SQUARE : vtkPlotPoints::CIRCLE);
    }
}

/// Fixes a log axis to the data's range [lo, hi] widened by half on each side: the automatic
/// range puts the extreme points on the frame, where the frame hides them.
void fixLogRange(vtkChart* chart, int axis, double lo, double hi) {
    if (!(lo > 0) || !(hi >= lo) || !std::isfinite(hi))
        return;
    vtkAxis* a = chart->GetAxis(axis);
    a->SetBehavior(vtkAxis::FIXED);
    a->SetUnscaledRange(lo / 1.5, hi * 1.5);
}

void plotRealtime(const Csv& csv, const std::string& dir) {
    // series: integrator, iterations, step (the explicit step differs per mesh: one series)
    std::vector<std::tuple<std::string, std::string, std::string>> keys;
    const auto keyOf = [&](int r) {
        const std::string integrator = csv.text(r, "integrator");
        return std::tuple{integrator, csv.text(r, "iterations"),
                          integrator == "symplectic-euler" ? std::string("its stable step")
                                                           : stepText(csv.number(r, "dt"))};
    };
    for (int r = 0; r < csv.rows(); ++r)
        if (std::find(keys.begin(), keys.end(), keyOf(r)) == keys.end())
            keys.push_back(keyOf(r));
    Panels panels(2, 1600, 640);
    vtkChart* factor = panels.chart(0);
    setupChart(factor, "Real-time factor (lines: boxes; dots: samples, cut or not)", "tets",
               "simulated s per wall s", true, true);
    double lo = INFINITY, hi = 0, low = INFINITY, high = 0; // tets, factors
    for (const auto& key : keys) {
        const auto& [integrator, iterations, step] = key;
        Points boxes, others;
        for (int r = 0; r < csv.rows(); ++r) {
            if (keyOf(r) != key || csv.text(r, "diverged") != "0")
                continue;
            const double tets = csv.number(r, "tets");
            lo = std::min(lo, tets);
            hi = std::max(hi, tets);
            const double factor = csv.number(r, "realtime_factor");
            low = std::min(low, factor);
            high = std::max(high, factor);
            (csv.text(r, "mesh").rfind("box-", 0) == 0 ? boxes : others).emplace_back(tets, factor);
        }
        const std::string label = integrator + (iterations.empty() ? "" : " " + iterations + " it") +
                                  ", " + step;
        addBoxesAndSamples(factor, label, boxes, others, integratorColour(integrator, iterations),
                           step == "1/60 s");
    }
    if (hi > 0)
        addSeries(factor, "real time (1x)", {{lo, 1.0}, {hi, 1.0}}, Rgb{80, 80, 80}, Style::Dashed, true,
                  true);
    fixLogRange(factor, vtkAxis::BOTTOM, lo, hi);
    fixLogRange(factor, vtkAxis::LEFT, std::min(low, 1.0), std::max(high, 1.0));

    vtkChart* cost = panels.chart(1);
    setupChart(cost, "Projective dynamics: factorisation (1 ms step)", "tets", "ms", true, true);
    if (auto* xy = vtkChartXY::SafeDownCast(cost)) // the costs rise to the right
        xy->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
    low = INFINITY, high = 0;
    for (const char* column : {"factor_ms", "refactor_ms"}) {
        Points boxes, others;
        for (int r = 0; r < csv.rows(); ++r)
            if (csv.text(r, "integrator") == "projective-dynamics" && csv.text(r, "iterations") == "5" &&
                stepText(csv.number(r, "dt")) == "1 ms" && !csv.text(r, column).empty()) {
                const double ms = csv.number(r, column);
                low = std::min(low, ms);
                high = std::max(high, ms);
                (csv.text(r, "mesh").rfind("box-", 0) == 0 ? boxes : others)
                    .emplace_back(csv.number(r, "tets"), ms);
            }
        addBoxesAndSamples(cost, std::string(column) == "factor_ms" ? "first factorisation" : "after a cut",
                           boxes, others, std::string(column) == "factor_ms" ? kEnhanced : kSubdivision, false);
    }
    fixLogRange(cost, vtkAxis::BOTTOM, lo, hi);
    fixLogRange(cost, vtkAxis::LEFT, low, high);
    writePng(panels.view, dir + "/realtime.png");
}

/// Fails unless an X display with GLX is reachable (VTK 9.1 aborts without one).
void requireDisplay() {
    if (const std::string problem = resect::plot::displayProblem(); !problem.empty())
        throw Failure{1, problem};
}

} // namespace

int main(int argc, char** argv) {
    std::string accuracyPath, scalingPath, resectionPath, realtimePath, outDir;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            const auto value = [&]() -> std::string {
                if (i + 1 >= argc)
                    throw Failure{2, a + ": missing value"};
                return argv[++i];
            };
            if (a == "--accuracy")
                accuracyPath = value();
            else if (a == "--scaling")
                scalingPath = value();
            else if (a == "--resection")
                resectionPath = value();
            else if (a == "--realtime")
                realtimePath = value();
            else if (a == "--out")
                outDir = value();
            else if (a == "--help" || a == "-h") {
                std::puts(
                    "usage: resect-plot [--accuracy accuracy_time.csv] [--scaling scaling.csv] "
                    "[--resection resection.csv] [--realtime realtime.csv] --out DIR");
                return 0;
            } else
                throw Failure{2, "unknown option " + a};
        }
        if (outDir.empty())
            throw Failure{2, "--out DIR is required"};
        if (accuracyPath.empty() && scalingPath.empty() && resectionPath.empty() && realtimePath.empty())
            throw Failure{2, "nothing to plot: give --accuracy, --scaling, --resection and/or --realtime"};
        // Read everything first: bad input is reported before any rendering.
        Csv accuracy, scaling, resection, realtime;
        std::vector<std::string> meshes;
        if (!accuracyPath.empty()) {
            accuracy = Csv::read(accuracyPath);
            for (int r = 0; r < accuracy.rows(); ++r)
                if (std::find(meshes.begin(), meshes.end(), accuracy.text(r, "mesh")) == meshes.end())
                    meshes.push_back(accuracy.text(r, "mesh"));
        }
        if (!scalingPath.empty())
            scaling = Csv::read(scalingPath);
        if (!resectionPath.empty()) {
            resection = Csv::read(resectionPath);
            // every number the plot reads, so that a malformed cell fails before rendering
            for (int r = 0; r < resection.rows(); ++r)
                for (const char* column :
                     {"pass", "worst_ratio_rel", "shortest_edge_rel", "tets_rel"})
                    resection.number(r, column);
        }
        if (!realtimePath.empty()) {
            realtime = Csv::read(realtimePath);
            for (int r = 0; r < realtime.rows(); ++r)
                for (const char* column : {"tets", "dt", "realtime_factor"})
                    realtime.number(r, column);
        }
        requireDisplay();
        for (const std::string& mesh : meshes) {
            plotCost(accuracy, mesh, outDir);
            plotD(accuracy, mesh, outDir);
        }
        if (!scalingPath.empty())
            plotScaling(scaling, outDir);
        if (!resectionPath.empty())
            plotResection(resection, outDir);
        if (!realtimePath.empty())
            plotRealtime(realtime, outDir);
        return 0;
    } catch (const Failure& f) {
        std::fprintf(stderr, "resect-plot: %s\n", f.message.c_str());
        return f.code;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "resect-plot: internal error: %s\n", e.what());
        return 1;
    }
}
