// A display for the workbench's controllers on a QCoreApplication: it records what it was told
// to draw, in order, instead of drawing (workbench/surface_display.h).
#pragma once

#include <QMetaObject>
#include <QObject>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "workbench/surface_display.h"

namespace ensil::test {

// What the controller asked the display to do, in order.
class RecordingDisplay : public workbench::SurfaceDisplay {
public:
    void setSurfaces(std::shared_ptr<const data::MeshSet> meshes) override {
        m_surfaces = std::move(meshes);
        if (!m_surfaces) m_motion.reset();
        calls.emplace_back(m_surfaces ? "surfaces" : "clear");
    }
    void setMotionSurfaces(std::shared_ptr<const data::MeshSet> meshes) override {
        m_motion = std::move(meshes);
        calls.emplace_back("motion");
        if (m_motion && motionArrived) motionArrived();
    }
    [[nodiscard]] std::shared_ptr<const data::MeshSet> surfaces() const override {
        return m_surfaces;
    }
    [[nodiscard]] const std::shared_ptr<const data::MeshSet>& motion() const { return m_motion; }
    void requestRepaint() override { calls.emplace_back("repaint"); }
    void beginInteraction() override {
        ++interactions;
        calls.emplace_back("begin");
    }
    void endInteraction() override {
        --interactions;
        calls.emplace_back("end");
    }
    void showPassingChange() override { calls.emplace_back("passing"); }
    // As a view does after its next frame: here at once, through the event loop.
    void afterNextFrame(QObject* context, std::function<void()> work) override {
        QMetaObject::invokeMethod(context, std::move(work), Qt::QueuedConnection);
    }

    std::vector<std::string> calls;
    int interactions = 0;
    std::function<void()> motionArrived;

private:
    std::shared_ptr<const data::MeshSet> m_surfaces;
    std::shared_ptr<const data::MeshSet> m_motion;
};

}  // namespace ensil::test
