#pragma once
// The undoable edits of a ScenarioDocument (widgets/scenario_document.h). Each command keeps
// what it needs to go both ways (the old and the new value, or the removed item and its
// index), changes the document's scenario in redo()/undo() and tells the document which
// part changed, so that the document's signals fire for the edit, its undo and its redo.
// Views do not create commands; they call ScenarioDocument's edit methods.

#include "scenario/scenario_document.h"

#include <QUndoCommand>

namespace resect {

class ScenarioDocument;

/// Base of every scenario edit: access to the document's scenario and its notification.
class ScenarioCommand : public QUndoCommand {
public:
    ScenarioCommand(ScenarioDocument& document, const QString& text);

protected:
    Scenario& scenario();
    /// Reports the changed parts (ScenarioDocument::Part flags) to the document.
    void notify(unsigned parts);

private:
    ScenarioDocument& m_document;
};

/// One cut setting (CutSettings), or all of them.
enum class CutField { All, Method, Triangulation, D, Snap, RelaxSteps, WSpring, WParticle, Damping,
                      Rings, Improve, ImproveQuality, ImproveShortEdge, ImproveCoarsen };

/// Replaces the cut settings. Consecutive commands for the same numeric field (d, relax
/// steps, the weights, damping, rings, the improvement's three factors) merge into one undo
/// step, so dragging the d slider is one step; a merge that brings the value back to where it
/// started leaves no step at all.
class SetCutSettingsCommand : public ScenarioCommand {
public:
    SetCutSettingsCommand(ScenarioDocument& document, CutSettings before, CutSettings after,
                          CutField field);
    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    CutSettings m_before;
    CutSettings m_after;
    CutField m_field;
};

/// Inserts a stroke at an index.
class AddStrokeCommand : public ScenarioCommand {
public:
    AddStrokeCommand(ScenarioDocument& document, Stroke stroke, int index);
    void redo() override;
    void undo() override;

private:
    Stroke m_stroke;
    int m_index;
};

/// Removes the stroke at an index (which must be valid when pushed).
class RemoveStrokeCommand : public ScenarioCommand {
public:
    RemoveStrokeCommand(ScenarioDocument& document, int index);
    void redo() override;
    void undo() override;

private:
    Stroke m_stroke;
    int m_index;
};

/// Inserts an explicit sweep at an index. A sweep naming a file keeps naming the same file
/// when the document is saved to another folder in between (its path is rebased).
class AddSweepCommand : public ScenarioCommand {
public:
    AddSweepCommand(ScenarioDocument& document, SweepSpec sweep, int index);
    void redo() override;
    void undo() override;

private:
    SweepSpec m_sweep;
    std::string m_baseDir; ///< the folder m_sweep.file is relative to
    int m_index;
};

/// Removes the explicit sweep at an index (which must be valid when pushed).
class RemoveSweepCommand : public ScenarioCommand {
public:
    RemoveSweepCommand(ScenarioDocument& document, int index);
    void redo() override;
    void undo() override;

private:
    SweepSpec m_sweep;
    std::string m_baseDir;
    int m_index;
};

/// Switches an effect on (inserting `effect` in the order of knownEffectNames()) or off
/// (removing the effect of that name, which must be present when pushed).
class SetEffectEnabledCommand : public ScenarioCommand {
public:
    SetEffectEnabledCommand(ScenarioDocument& document, EffectSpec effect, bool enable);
    void redo() override;
    void undo() override;

private:
    void insert();
    void remove();

    EffectSpec m_effect;
    bool m_enable;
    int m_index = -1; ///< where the effect is (or was) in the list
};

/// Replaces the parameters of an effect that is on. Consecutive commands for the same effect
/// merge into one undo step (typing a value, stepping a spin box).
class SetEffectParametersCommand : public ScenarioCommand {
public:
    SetEffectParametersCommand(ScenarioDocument& document, std::string name, QJsonObject before,
                               QJsonObject after);
    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void set(const QJsonObject& parameters);

    std::string m_name;
    QJsonObject m_before;
    QJsonObject m_after;
};

/// Replaces the first tissue's fixed regions. Consecutive commands with the same merge key
/// (>= 0: one region's index) merge into one undo step; -1 never merges.
class SetFixedRegionsCommand : public ScenarioCommand {
public:
    SetFixedRegionsCommand(ScenarioDocument& document, std::vector<FixedRegion> before,
                           std::vector<FixedRegion> after, int mergeKey);
    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    std::vector<FixedRegion> m_before;
    std::vector<FixedRegion> m_after;
    int m_mergeKey;
};

/// Changes nothing and is never added: it is obsolete from the start, and QUndoStack::push
/// deletes such a command after deleting the commands above the current index. Pushed by
/// ScenarioDocument::revertTo to drop the edits it undid (no redo of them is left).
class DropRedoCommand : public ScenarioCommand {
public:
    explicit DropRedoCommand(ScenarioDocument& document);
    void redo() override {}
    void undo() override {}
};

/// Sets metadata.title; consecutive title edits (typing) merge into one undo step.
class SetTitleCommand : public ScenarioCommand {
public:
    SetTitleCommand(ScenarioDocument& document, std::string before, std::string after);
    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    std::string m_before;
    std::string m_after;
};

} // namespace resect
