#include "scenario/sweep_io.h"

#include "scenario/atomic_file.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace resect {

Status parseSweep(const QByteArray& json, const std::string& name, SweepSurface& out) {
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &error);
    if (error.error != QJsonParseError::NoError)
        return Status::error(name + ": not valid JSON (" + error.errorString().toStdString() +
                             " at offset " + std::to_string(error.offset) + ")");
    if (!doc.isObject())
        return Status::error(name + ": expected a JSON object with \"curves\"");
    const QJsonValue curvesValue = doc.object().value("curves");
    if (!curvesValue.isArray())
        return Status::error(name + ": curves: missing or not an array");
    const QJsonArray curves = curvesValue.toArray();
    std::vector<std::vector<Vec3>> points;
    for (qsizetype i = 0; i < curves.size(); ++i) {
        const std::string at = name + ": curves[" + std::to_string(i) + "]";
        if (!curves[i].isArray())
            return Status::error(at + ": expected an array of points");
        const QJsonArray curve = curves[i].toArray();
        std::vector<Vec3> c;
        for (qsizetype j = 0; j < curve.size(); ++j) {
            const QJsonArray p = curve[j].toArray();
            const bool ok = curve[j].isArray() && p.size() == 3 && p[0].isDouble() && p[1].isDouble() &&
                            p[2].isDouble() && std::isfinite(p[0].toDouble()) &&
                            std::isfinite(p[1].toDouble()) && std::isfinite(p[2].toDouble());
            if (!ok)
                return Status::error(at + "[" + std::to_string(j) + "]: expected [x, y, z] with finite numbers");
            c.emplace_back(p[0].toDouble(), p[1].toDouble(), p[2].toDouble());
        }
        points.push_back(std::move(c));
    }
    if (Status s = SweepSurface::fromCurves(points, out); !s.ok())
        return Status::error(name + ": " + s.message());
    return Status::success();
}

Status readSweep(const std::string& path, SweepSurface& out) {
    QFile file(QString::fromStdString(path));
    if (!file.exists())
        return Status::error(path + ": no such file");
    if (!file.open(QIODevice::ReadOnly))
        return Status::error(path + ": cannot open (" + file.errorString().toStdString() + ")");
    constexpr qint64 kMaxBytes = 256ll << 20;
    if (file.size() > kMaxBytes)
        return Status::error(path + ": larger than 256 MiB; not a sweep file");
    return parseSweep(file.readAll(), path, out);
}

Status writeSweep(const std::string& path, const SweepSurface& sweep) {
    QJsonArray curves;
    for (const auto& c : sweep.curves()) {
        QJsonArray curve;
        for (const Vec3& p : c)
            curve.append(QJsonArray{p.x(), p.y(), p.z()});
        curves.append(curve);
    }
    const QByteArray text = QJsonDocument(QJsonObject{{"curves", curves}}).toJson(QJsonDocument::Compact);
    return writeFileAtomically(path, std::string_view(text.constData(), static_cast<std::size_t>(text.size())));
}

} // namespace resect
