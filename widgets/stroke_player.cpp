#include "widgets/stroke_player.h"

#include "scenario/scenario_sweeps.h"
#include "widgets/vtk_viewport.h"

#include <QTimer>

#include <algorithm>
#include <cmath>

namespace resect {

StrokePlayer::StrokePlayer(VtkViewport* viewport, QObject* parent)
    : QObject(parent), m_viewport(viewport), m_timer(new QTimer(this)) {
    m_timer->setInterval(kDefaultIntervalMs);
    connect(m_timer, &QTimer::timeout, this, &StrokePlayer::tick);
    if (m_viewport != nullptr)
        for (vtkProp* prop : m_toolActor.props())
            m_viewport->addProp(prop);
}

StrokePlayer::~StrokePlayer() {
    if (m_viewport != nullptr)
        for (vtkProp* prop : m_toolActor.props())
            m_viewport->removeProp(prop);
}

void StrokePlayer::setStroke(const ToolSpec& tool, const Stroke& stroke) {
    pause();
    m_tool = tool;
    m_stroke = stroke;
    m_time = startTime();
    showPose();
    emit timeChanged(m_time);
}

double StrokePlayer::startTime() const {
    return hasStroke() ? m_stroke.poses.front().t : 0.0;
}

double StrokePlayer::endTime() const {
    return hasStroke() ? m_stroke.poses.back().t : 0.0;
}

ToolPose StrokePlayer::currentPose() const {
    return poseAt(m_stroke, m_time);
}

bool StrokePlayer::isPlaying() const {
    return m_timer->isActive();
}

void StrokePlayer::setSpeed(double factor) {
    if (std::isfinite(factor) && factor > 0)
        m_speed = factor;
}

void StrokePlayer::setInterval(int ms) {
    m_timer->setInterval(std::max(1, ms));
}

void StrokePlayer::play() {
    if (!hasStroke() || isPlaying())
        return;
    if (m_time >= endTime())
        setTime(startTime());
    m_sinceTick.start();
    m_timer->start();
    emit playingChanged(true);
}

void StrokePlayer::pause() {
    if (!isPlaying())
        return;
    m_timer->stop();
    emit playingChanged(false);
}

void StrokePlayer::stop() {
    pause();
    setTime(startTime());
}

void StrokePlayer::setTime(double t) {
    if (!std::isfinite(t))
        return;
    const double clamped = std::clamp(t, startTime(), std::max(startTime(), endTime()));
    if (clamped == m_time)
        return;
    m_time = clamped;
    showPose();
    emit timeChanged(m_time);
}

void StrokePlayer::advance(double seconds) {
    if (!hasStroke() || !std::isfinite(seconds))
        return;
    setTime(m_time + seconds);
    if (isPlaying() && m_time >= endTime()) {
        pause();
        emit finished();
    }
}

void StrokePlayer::tick() {
    const double elapsed = double(m_sinceTick.nsecsElapsed()) * 1e-9;
    m_sinceTick.restart();
    advance(elapsed * m_speed);
}

void StrokePlayer::showPose() {
    if (hasStroke())
        m_toolActor.setPose(m_tool, currentPose());
    else
        m_toolActor.hide();
    if (m_viewport != nullptr)
        m_viewport->requestRender();
}

} // namespace resect
