#include "scenario/scenario_migrate.h"

#include <QJsonArray>

#include <string>

namespace resect {

namespace {

/// Moves `from[key]` (if present) to `to[newKey]`.
void move(QJsonObject& from, const char* key, QJsonObject& to, const char* newKey) {
    if (from.contains(key))
        to.insert(newKey, from.take(key));
}

QJsonObject migrateTissue(QJsonObject t, ScenarioDiagnostics& diag) {
    QJsonObject out;
    out["name"] = "tissue";
    move(t, "surface", out, "surface");
    move(t, "mesh", out, "mesh");
    QJsonObject meshing;
    move(t, "edge_length", meshing, "edge_length");
    move(t, "seed", meshing, "seed");
    if (!meshing.isEmpty())
        out["meshing"] = meshing;
    QJsonObject material;
    move(t, "density", material, "density");
    move(t, "stiffness", material, "stiffness");
    move(t, "damping", material, "damping");
    if (!material.isEmpty())
        out["material"] = material;
    if (t.contains("fixed_box")) {
        const QJsonValue box = t.take("fixed_box");
        const QJsonArray a = box.toArray();
        bool ok = box.isArray() && a.size() == 6;
        for (qsizetype i = 0; ok && i < a.size(); ++i)
            ok = a[i].isDouble();
        if (ok)
            out["fixed_regions"] = QJsonArray{QJsonObject{{"min", QJsonArray{a[0], a[1], a[2]}},
                                                          {"max", QJsonArray{a[3], a[4], a[5]}}}};
        else
            diag.error("tissue.fixed_box", "expected [x0, y0, z0, x1, y1, z1] (6 numbers)");
    }
    for (auto it = t.begin(); it != t.end(); ++it)
        out.insert(it.key(), it.value()); // anything else: carried over
    return out;
}

QJsonObject migrateTool(QJsonObject t) {
    QJsonObject out;
    move(t, "points", out, "curve");
    move(t, "scale", out, "size");
    for (auto it = t.begin(); it != t.end(); ++it)
        out.insert(it.key(), it.value());
    return out;
}

QJsonArray migrateStrokes(const QJsonArray& strokes, ScenarioDiagnostics& diag) {
    QJsonArray out;
    for (qsizetype i = 0; i < strokes.size(); ++i) {
        const std::string path = "strokes[" + std::to_string(i) + "]";
        if (!strokes[i].isArray()) {
            diag.error(path, "expected an array of poses (version 0)");
            continue;
        }
        QJsonArray poses;
        for (const QJsonValue& p : strokes[i].toArray()) {
            QJsonObject pose = p.toObject();
            if (p.isObject() && pose.contains("rotation") && !pose.contains("orientation"))
                pose.insert("orientation", pose.take("rotation"));
            poses.append(p.isObject() ? QJsonValue(pose) : p); // non-objects: reported later
        }
        out.append(QJsonObject{{"poses", poses}});
    }
    return out;
}

} // namespace

QJsonObject migrateScenarioV0(const QJsonObject& v0, ScenarioDiagnostics& diag) {
    diag.warning("version",
                 "version 0 migrated to version 1 (saving writes version 1); paths in later "
                 "messages refer to the version-1 layout");
    QJsonObject in = v0;
    QJsonObject out;
    out["format"] = in.take("format");
    in.remove("version");
    out["version"] = 1;

    QJsonObject metadata;
    move(in, "title", metadata, "title");
    move(in, "author", metadata, "author");
    move(in, "description", metadata, "description");
    out["metadata"] = metadata;

    if (in.contains("tissue")) {
        const QJsonValue t = in.take("tissue");
        if (t.isObject())
            out["tissues"] = QJsonArray{migrateTissue(t.toObject(), diag)};
        else
            diag.error("tissue", "expected an object (version 0)");
    } else {
        diag.error("tissue", "missing (version 0 has one \"tissue\" object)");
    }

    if (in.contains("tool")) {
        const QJsonValue t = in.take("tool");
        if (t.isObject())
            out["tool"] = migrateTool(t.toObject());
        else
            diag.error("tool", "expected an object (version 0)");
    }

    if (in.contains("strokes")) {
        const QJsonValue s = in.take("strokes");
        if (s.isArray())
            out["strokes"] = migrateStrokes(s.toArray(), diag);
        else
            diag.error("strokes", "expected an array of strokes (version 0)");
    }

    if (in.contains("sweeps")) {
        const QJsonValue s = in.take("sweeps");
        if (s.isArray()) {
            QJsonArray sweeps;
            const QJsonArray a = s.toArray();
            for (qsizetype i = 0; i < a.size(); ++i) {
                if (a[i].isString())
                    sweeps.append(QJsonObject{{"file", a[i]}});
                else
                    diag.error("sweeps[" + std::to_string(i) + "]",
                               "expected a file name (version 0)");
            }
            out["sweeps"] = sweeps;
        } else {
            diag.error("sweeps", "expected an array of file names (version 0)");
        }
    }

    if (in.contains("cut")) {
        const QJsonValue c = in.take("cut");
        if (c.isObject()) {
            QJsonObject cut = c.toObject();
            if (cut.contains("threshold"))
                cut.insert("d", cut.take("threshold"));
            out["cut_settings"] = cut;
        } else {
            diag.error("cut", "expected an object (version 0)");
        }
    }

    if (in.contains("effects")) {
        const QJsonValue e = in.take("effects");
        if (e.isArray()) {
            QJsonArray effects;
            const QJsonArray a = e.toArray();
            for (qsizetype i = 0; i < a.size(); ++i) {
                if (a[i].isString())
                    effects.append(QJsonObject{{"name", a[i]}, {"parameters", QJsonObject{}}});
                else
                    diag.error("effects[" + std::to_string(i) + "]",
                               "expected an effect name (version 0)");
            }
            out["effects"] = effects;
        } else {
            diag.error("effects", "expected an array of effect names (version 0)");
        }
    }

    QJsonObject simulation;
    if (in.contains("integrator")) {
        const QJsonValue i = in.take("integrator");
        if (i == QJsonValue("explicit"))
            simulation["integrator"] = "symplectic-euler";
        else if (i == QJsonValue("implicit"))
            simulation["integrator"] = "backward-euler";
        else
            diag.error("integrator", "expected \"explicit\" or \"implicit\" (version 0)");
    }
    move(in, "time_step", simulation, "time_step");
    move(in, "duration", simulation, "duration");
    if (!simulation.isEmpty())
        out["simulation"] = simulation;

    if (in.contains("expect")) {
        const QJsonValue e = in.take("expect");
        if (e.isObject()) {
            QJsonObject expect = e.toObject();
            QJsonArray expectations;
            if (expect.contains("pieces"))
                expectations.append(
                    QJsonObject{{"kind", "pieces_at_least"}, {"value", expect.take("pieces")}});
            if (expect.contains("min_radius_ratio"))
                expectations.append(QJsonObject{{"kind", "min_radius_ratio_at_least"},
                                                {"value", expect.take("min_radius_ratio")}});
            for (auto it = expect.begin(); it != expect.end(); ++it)
                diag.error("expect." + it.key().toStdString(),
                           "unknown expectation (version 0 knows pieces and min_radius_ratio)");
            out["expectations"] = expectations;
        } else {
            diag.error("expect", "expected an object (version 0)");
        }
    }

    for (auto it = in.begin(); it != in.end(); ++it) {
        if (!out.contains(it.key()))
            out.insert(it.key(), it.value()); // unknown top-level fields: carried over
        else
            diag.warning(it.key().toStdString(),
                         "dropped: a version-0 document cannot have this version-1 field");
    }
    return out;
}

} // namespace resect
