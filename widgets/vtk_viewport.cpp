#include "widgets/vtk_viewport.h"

#include "widgets/opengl_support.h"
#include "widgets/viewport_tool.h"
#include "widgets/vtk_gl_widget.h"

#include <QLabel>
#include <QMouseEvent>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkProp.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace resect {

namespace {

/// Union of two bounds; an invalid operand is ignored.
Bounds unite(const Bounds& a, const Bounds& b) {
    if (!validBounds(a))
        return b;
    if (!validBounds(b))
        return a;
    Bounds u;
    for (int i = 0; i < 3; ++i) {
        u[2 * i] = std::min(a[2 * i], b[2 * i]);
        u[2 * i + 1] = std::max(a[2 * i + 1], b[2 * i + 1]);
    }
    return u;
}

/// Zoom per pixel of a zoom drag and per 15-degree wheel step.
constexpr double kZoomPerPixel = 1.01;
constexpr double kZoomPerWheelStep = 1.1;
/// An oblique default view: looking along +y, slightly from above and the side, z up.
constexpr std::array<double, 3> kStartingDirection{-0.45, 1.0, -0.35};
constexpr std::array<double, 3> kStartingUp{0.0, 0.0, 1.0};
/// Share of the width, centred, into which framing fits the scene's bounding sphere while a
/// colour legend is shown (the legend starts at 0.8 of the width). The sphere is wider than
/// any outline in it, so 0.75 keeps a cube's outline left of 0.8 (0.6 would be exact for the
/// sphere, but shrinks the tissue to a third of the view).
constexpr double kLegendFreeShare = 0.75;

} // namespace

VtkViewport::VtkViewport(QWidget* parent) : QWidget(parent) {
    m_layout = new QVBoxLayout(this);
    m_layout->setContentsMargins(0, 0, 0, 0);
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::StrongFocus);

    m_camera.setViewDirection(kStartingDirection, kStartingUp);

    QString reason;
    if (openGlAvailable(&reason))
        createGlWidget();
    else
        showPlaceholder(reason);
}

VtkViewport::~VtkViewport() = default;

void VtkViewport::createGlWidget() {
    m_glWidget = new VtkGlWidget(this);
    // The viewport handles the mouse for both the GL widget and the placeholder.
    m_glWidget->setAttribute(Qt::WA_TransparentForMouseEvents);
    vtkRenderer* renderer = m_glWidget->renderer();
    renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
    // Opaque: Qt composes the widget's framebuffer with its alpha, and VTK's default
    // background alpha of 0 would let the window colour show through.
    renderer->SetBackgroundAlpha(1.0);
    renderer->SetActiveCamera(m_camera.camera());
    for (vtkProp* prop : m_tetMesh.props())
        renderer->AddViewProp(prop);
    for (vtkProp* prop : m_surface.props())
        renderer->AddViewProp(prop);
    for (vtkProp* prop : m_chips.props())
        renderer->AddViewProp(prop);
    for (vtkProp* prop : m_chipSurfaces.props())
        renderer->AddViewProp(prop);
    for (vtkProp* prop : m_props)
        renderer->AddViewProp(prop);
    connect(m_glWidget, &VtkGlWidget::frameRendered, this, &VtkViewport::frameRendered);
    connect(m_glWidget, &VtkGlWidget::initializationFailed, this,
            &VtkViewport::onGlInitializationFailed);
    m_layout->addWidget(m_glWidget);
}

void VtkViewport::showPlaceholder(const QString& reason) {
    m_unavailableReason = reason;
    if (m_placeholder == nullptr) {
        m_placeholder = new QLabel(this);
        m_placeholder->setObjectName(QStringLiteral("viewportPlaceholder"));
        m_placeholder->setAlignment(Qt::AlignCenter);
        m_placeholder->setWordWrap(true);
        m_placeholder->setAttribute(Qt::WA_TransparentForMouseEvents);
        m_placeholder->setAutoFillBackground(true);
        m_layout->addWidget(m_placeholder);
    }
    updatePlaceholderText();
    m_placeholder->show();
}

void VtkViewport::updatePlaceholderText() {
    if (m_placeholder == nullptr)
        return;
    QString text = tr("3-D view unavailable: %1.").arg(m_unavailableReason);
    if (m_tetCount > 0)
        text += QLatin1Char('\n') +
                tr("Tet mesh loaded: %1 nodes, %2 tets.").arg(m_nodeCount).arg(m_tetCount);
    if (m_triangleCount > 0)
        text += QLatin1Char('\n') + tr("Surface loaded: %1 triangles.").arg(m_triangleCount);
    m_placeholder->setText(text);
}

void VtkViewport::onGlInitializationFailed(const QString& reason) {
    if (m_glWidget != nullptr) {
        m_layout->removeWidget(m_glWidget);
        m_glWidget->hide();
        m_glWidget->deleteLater();
        m_glWidget = nullptr;
    }
    showPlaceholder(reason);
    emit renderingUnavailable(reason);
}

void VtkViewport::setTetMesh(const TetMesh& mesh, bool frame) {
    m_tetMesh.setMesh(mesh);
    m_nodeCount = mesh.nodeCount();
    m_tetCount = mesh.tetCount();
    updatePlaceholderText();
    if (frame) {
        resetCamera();
    } else {
        m_camera.fitClippingRange(sceneBounds());
        requestRender();
    }
}

void VtkViewport::setSurface(const TriangleSurface& surface, bool frameIfAlone) {
    const bool frame = frameIfAlone && m_tetMesh.empty();
    m_surface.setSurface(surface);
    m_triangleCount = surface.triangleCount();
    updatePlaceholderText();
    if (frame)
        resetCamera();
    else
        requestRender();
}

void VtkViewport::clear() {
    m_tetMesh.clear();
    m_surface.clear();
    m_chips.clear();
    m_chipSurfaces.clear();
    m_nodeCount = m_tetCount = m_triangleCount = 0;
    updatePlaceholderText();
    requestRender();
}

void VtkViewport::addProp(vtkProp* prop) {
    if (prop == nullptr || std::find(m_props.begin(), m_props.end(), prop) != m_props.end())
        return;
    m_props.push_back(prop);
    if (m_glWidget != nullptr)
        m_glWidget->renderer()->AddViewProp(prop);
    requestRender();
}

void VtkViewport::removeProp(vtkProp* prop) {
    const auto it = std::find(m_props.begin(), m_props.end(), prop);
    if (it == m_props.end())
        return;
    m_props.erase(it);
    if (m_glWidget != nullptr)
        m_glWidget->renderer()->RemoveViewProp(prop);
    requestRender();
}

void VtkViewport::setTool(ViewportTool* tool) {
    if (tool == m_tool)
        return;
    ViewportTool* previous = m_tool;
    m_tool = tool;
    m_toolGrab = false;
    if (previous != nullptr)
        previous->deactivated(*this);
}

Bounds VtkViewport::sceneBounds() const {
    return unite(unite(m_tetMesh.bounds(), m_surface.bounds()),
                 unite(m_chips.bounds(), m_chipSurfaces.bounds()));
}

void VtkViewport::resetCamera() {
    const Bounds bounds = sceneBounds();
    if (!validBounds(bounds))
        return;
    double aspect = height() > 0 ? double(width()) / double(height()) : 1.0;
    // A visible colour legend (QualityLegend: a scalar bar from 0.8 of the width rightwards)
    // must not cover the tissue: frame it into the middle kLegendFreeShare of the width.
    for (vtkProp* prop : m_props)
        if (prop->IsA("vtkScalarBarActor") && prop->GetVisibility()) {
            aspect *= kLegendFreeShare;
            break;
        }
    m_camera.reset(bounds, aspect);
    cameraMoved();
}

void VtkViewport::restoreStartingView() {
    m_camera.setViewDirection(kStartingDirection, kStartingUp);
    resetCamera();
}

void VtkViewport::sceneExtentChanged() {
    m_camera.fitClippingRange(sceneBounds());
    requestRender();
}

bool VtkViewport::hasRendering() const {
    return m_glWidget != nullptr && !m_glWidget->hasFailed();
}

QImage VtkViewport::grabImage() {
    if (hasRendering())
        return m_glWidget->grabFramebuffer();
    return grab().toImage();
}

void VtkViewport::requestRender() {
    if (m_glWidget != nullptr)
        m_glWidget->update();
}

void VtkViewport::cameraMoved() {
    m_camera.fitClippingRange(sceneBounds());
    requestRender();
    emit cameraChanged();
}

void VtkViewport::mousePressEvent(QMouseEvent* event) {
    if (m_drag == Drag::None && m_tool != nullptr && m_tool->mousePress(*this, event)) {
        m_toolGrab = true;
        event->accept();
        return;
    }
    const Qt::KeyboardModifiers mods = event->modifiers();
    switch (event->button()) {
    case Qt::LeftButton:
        m_drag = (mods & Qt::ShiftModifier)     ? Drag::Pan
                 : (mods & Qt::ControlModifier) ? Drag::Zoom
                                                : Drag::Orbit;
        break;
    case Qt::MiddleButton:
        m_drag = Drag::Pan;
        break;
    case Qt::RightButton:
        m_drag = Drag::Zoom;
        break;
    default:
        QWidget::mousePressEvent(event);
        return;
    }
    m_lastPos = event->position().toPoint();
    event->accept();
}

void VtkViewport::mouseMoveEvent(QMouseEvent* event) {
    // A tool sees hover moves too (no button held) and the drags it started.
    if (m_tool != nullptr && (m_toolGrab || m_drag == Drag::None) &&
        m_tool->mouseMove(*this, event)) {
        event->accept();
        return;
    }
    if (m_drag == Drag::None) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    const QPoint pos = event->position().toPoint();
    const QPoint delta = pos - m_lastPos;
    m_lastPos = pos;
    if (delta.isNull())
        return;
    const double h = std::max(1, height());
    switch (m_drag) {
    case Drag::Orbit:
        m_camera.orbit(delta.x(), delta.y(), h);
        break;
    case Drag::Pan:
        m_camera.pan(delta.x(), delta.y(), h);
        break;
    case Drag::Zoom:
        // Dragging up zooms in.
        m_camera.zoom(std::pow(kZoomPerPixel, -delta.y()));
        break;
    case Drag::None:
        break;
    }
    cameraMoved();
    event->accept();
}

void VtkViewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_toolGrab) {
        m_toolGrab = false;
        if (m_tool != nullptr)
            m_tool->mouseRelease(*this, event);
        event->accept();
        return;
    }
    if (m_drag == Drag::None) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    m_drag = Drag::None;
    event->accept();
}

void VtkViewport::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0) {
        QWidget::wheelEvent(event);
        return;
    }
    m_camera.zoom(std::pow(kZoomPerWheelStep, steps));
    cameraMoved();
    event->accept();
}

} // namespace resect
