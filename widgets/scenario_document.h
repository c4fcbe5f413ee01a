#pragma once
// ScenarioDocument: the studio's document model (issue 8), the single source of truth that
// the views observe. It owns one resect::Scenario (scenario/scenario_document.h) and a
// QUndoStack; every edit is an undoable command (widgets/scenario_commands.h), so views
// never write to the scenario directly: they call the edit methods below and listen to the
// signals, which fire for the edit itself and again for its undo and redo.
//
// Files:
//  - open() reads and validates (scenario_load.h); on failure the document is unchanged and
//    the message lists every error, one per line, each naming the JSON path. open(),
//    newFromSample() and newFromAnatomy() are a read step (readScenario, sampleScenario,
//    anatomyScenario: a Scenario, the document untouched) followed by replace(); the studio
//    runs the two apart, deriving the tissue in between (DocumentOpener), so that a file
//    whose tissue or cuts fail never replaces the open document;
//  - save()/saveAs() first ask the save check (setSaveCheck: the studio refuses to save a
//    state whose tissue and cuts have not derived);
//  - save()/saveAs() write atomically through saveScenario (a failed save leaves the old
//    file as it was) and mark the undo stack clean; isModified() is "not at the clean state";
//  - recent files live in QSettings (key kRecentFilesKey, at most kMaxRecentFiles, most
//    recent first, no duplicates); the settings are the application's (organisation and
//    application name) unless a QSettings is injected with setSettings() (tests);
//  - autosave: autosaveNow() (or the timer of setAutosaveInterval) writes a modified document
//    to kAutosaveFileName in autosaveDirectory() (QStandardPaths::AppLocalDataLocation unless
//    set), with kAutosaveInfoFileName naming the file it belongs to. A clean save, close()
//    or loading another document removes the autosave this document wrote; destroying the
//    object does not (a crash and a plain exit look the same), so the main window calls
//    close() after its unsaved-changes prompt. At start-up, before loading anything, it asks
//    recoverableAutosave() and offers recover() or discardAutosave().
//    There is one autosave per autosave folder: two studios running at once share it.
//
// Refused edits: revertTo() undoes the latest edits back to the nearest earlier state a
// predicate accepts and drops them from the undo stack (TissueSession calls it when a state
// of the document does not derive: the document never keeps such a state).

#include "scenario/scenario_document.h"
#include "scenario/scene_defaults.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <QUndoStack>

#include <functional>
#include <memory>

class QSettings;

namespace resect {

class ScenarioCommand;

class ScenarioDocument : public QObject {
    Q_OBJECT

public:
    static constexpr int kMaxRecentFiles = 8;
    static constexpr const char* kRecentFilesKey = "recentFiles";
    static constexpr const char* kAutosaveFileName = "autosave.resect.json";
    static constexpr const char* kAutosaveInfoFileName = "autosave.info.json";
    /// Radius (mm) of the tool-contact effect when it is switched on for the first time
    /// (the effect requires one; scenario/scene_defaults.h).
    static constexpr double kDefaultToolContactRadius = resect::kDefaultToolContactRadius;

    /// Which part of the scenario an edit touched (commands report it; see notify()).
    enum Part : unsigned {
        CutSettingsPart = 1u << 0,
        StrokesPart = 1u << 1,
        SweepsPart = 1u << 2,
        EffectsPart = 1u << 3,
        MetadataPart = 1u << 4,
        FixedRegionsPart = 1u << 5, ///< the first tissue's fixed regions
        AllParts = 0xffu,
    };

    explicit ScenarioDocument(QObject* parent = nullptr);
    ~ScenarioDocument() override;

    const Scenario& scenario() const { return m_scenario; }
    QUndoStack* undoStack() { return &m_undo; }
    /// The file the document was opened from or saved to; empty for a new document.
    const QString& filePath() const { return m_filePath; }
    /// The file name, or "untitled" for a new document (for the window title).
    QString displayName() const;
    bool isModified() const { return !m_undo.isClean(); }

    // ---- Files ------------------------------------------------------------------------
    /// A new, unsaved document with the built-in anatomy "sample:NAME" (polyp or myoma), a
    /// default tool (a half loop, 7 mm wide), default cut settings and a new scene's defaults
    /// (scenario/scene_defaults.h): the base anchored by a fixed region, the deformation,
    /// fixed and damping effects; valid as it is and ready to simulate. False (document
    /// unchanged) for an unknown name.
    bool newFromSample(const QString& name, QString* error = nullptr);
    /// A new, unsaved document whose tissue is the anatomy in `path`: a tet mesh (.vtu, .msh,
    /// .node, .ele) used as it is, or any surface assimp reads, meshed coarsely when the
    /// tissue is loaded (TissueSession); the deformation and damping effects (its base is not
    /// known before it is loaded: switching the fixed effect on anchors it, fixRegion). The
    /// file is only checked to exist here; reading errors come from loading. False (document
    /// unchanged) if there is no such file.
    bool newFromAnatomy(const QString& path, QString* error = nullptr);
    /// Reads and validates `path`. On failure returns false, the document is unchanged and
    /// *error lists every error (one per line, "FILE: PATH: MESSAGE").
    bool open(const QString& path, QString* error = nullptr);

    /// The read steps of open(), newFromSample() and newFromAnatomy(): the scenario they would
    /// make (false, with the reason, where they fail). The document is not touched.
    static bool readScenario(const QString& path, Scenario& out, QString* error = nullptr);
    static bool sampleScenario(const QString& name, Scenario& out, QString* error = nullptr);
    static bool anatomyScenario(const QString& path, Scenario& out, QString* error = nullptr);
    /// Replaces the document (not undoable: the undo stack is cleared) by `scenario`, made by
    /// one of the read steps above: read from the scenario file `filePath` (made absolute; it
    /// heads the recent files), or, with an empty path, a new untitled document.
    void replace(Scenario scenario, const QString& filePath = QString());
    /// Saves to filePath() (an error if there is none). See saveAs().
    bool save(QString* error = nullptr);
    /// What save() and saveAs() ask before writing: a non-empty answer is the reason not to
    /// save, and they fail with it (the document, its file and the file on disk unchanged).
    /// Null: no check.
    void setSaveCheck(std::function<QString()> check) { m_saveCheck = std::move(check); }
    /// Validates and writes atomically (saveScenario); on success the document's file is
    /// `path`, its relative paths are rebased to the new folder, the undo stack is clean, the
    /// file heads the recent files and this document's autosave is removed. On failure the
    /// document, its file name and any existing file at `path` are unchanged.
    bool saveAs(const QString& path, QString* error = nullptr);
    /// Closes the document: an empty scenario, no file, a clear undo stack; removes this
    /// document's autosave. (The caller asks about unsaved changes first.)
    void close();

    // ---- Recent files -------------------------------------------------------------------
    /// Not owned; must outlive the document. Null: the application's QSettings.
    void setSettings(QSettings* settings) { m_settings = settings; }
    QStringList recentFiles() const;
    /// Puts `path` (made absolute) first, removing an older entry for it and anything beyond
    /// kMaxRecentFiles. open() and saveAs() call it.
    void addRecentFile(const QString& path);
    void clearRecentFiles();

    // ---- Autosave -----------------------------------------------------------------------
    /// Empty: QStandardPaths::AppLocalDataLocation.
    void setAutosaveDirectory(const QString& dir) { m_autosaveDir = dir; }
    QString autosaveDirectory() const;
    QString autosavePath() const;
    /// Calls autosaveNow() every `ms` milliseconds; 0 stops it.
    void setAutosaveInterval(int ms);
    /// Writes the document to the autosave file if it is modified (atomically, not
    /// validated: an unfinished edit is still worth keeping). True if written or nothing to
    /// do.
    bool autosaveNow(QString* error = nullptr);
    /// The autosave file if one is there that a crashed session left behind and that is
    /// newer than the file it belongs to (or belongs to no file); empty otherwise.
    QString recoverableAutosave() const;
    /// The file the recoverable autosave belongs to; empty for an untitled document.
    QString autosaveOriginalFile() const;
    /// Loads the autosave as a modified document (its file name is the file it belongs to,
    /// if any). The autosave stays until the document is saved or closed.
    bool recover(QString* error = nullptr);
    /// Removes the autosave files (the user chose not to recover).
    void discardAutosave();

    // ---- Edits (each pushes one undoable command; an edit that changes nothing pushes
    // none). Consecutive changes of the same numeric setting merge into one undo step.
    void setCutSettings(const CutSettings& settings);
    void setMethod(CutMethod method);
    void setTriangulation(FaceTriangulation triangulation);
    void setD(double d);
    void setSnap(bool snap);
    void setRelaxSteps(int steps);
    void setWSpring(double w);
    void setWParticle(double w);
    void setRelaxDamping(double damping);
    void setRings(int rings);
    /// The mesh improvement after every cut (CutSettings::improve...; the factors' ranges are
    /// CutLimits').
    void setImprove(bool improve);
    void setImproveQuality(double factor);
    void setImproveShortEdge(double factor);
    void setImproveCoarsen(double factor);

    /// Inserts at `index` (-1 or out of range: appends).
    void addStroke(const Stroke& stroke, int index = -1);
    /// False for an index out of range.
    bool removeStroke(int index);
    void addSweep(const SweepSpec& sweep, int index = -1);
    bool removeSweep(int index);

    bool isEffectEnabled(const QString& name) const;
    /// Adds or removes the named effect (knownEffectNames()); an effect switched back on gets
    /// the parameters it had when it was switched off (else defaultEffectParameters,
    /// scenario/scene_defaults.h). False for an unknown name.
    bool setEffectEnabled(const QString& name, bool enabled);
    bool toggleEffect(const QString& name);
    /// Replaces the parameters of an effect that is on (scenario_document.h's table; they are
    /// validated by deriving the state, TissueSession). Consecutive changes of one effect's
    /// parameters merge into one undo step. False if the effect is not on.
    bool setEffectParameters(const QString& name, const QJsonObject& parameters);

    /// The first tissue's fixed regions (boxes in reference coordinates, mm; the nodes inside
    /// are anchored: held by the fixed effect, and what tells the tissue from resected chips).
    /// Empty without a tissue.
    const std::vector<FixedRegion>& fixedRegions() const;
    /// Appends a region to the first tissue's. False without a tissue.
    bool addFixedRegion(const FixedRegion& region);
    /// Replaces region `index`; consecutive changes of one region (typing, dragging a handle)
    /// merge into one undo step. False for an index out of range.
    bool setFixedRegion(int index, const FixedRegion& region);
    /// Removes region `index`. Removing the last region while the fixed effect is on switches
    /// the effect off too, in the same undo step (the effect needs a region). False for an
    /// index out of range.
    bool removeFixedRegion(int index);
    /// Switches the fixed effect on; if the first tissue has no fixed region, `region` is
    /// added first, in the same undo step (the effect needs one). False without a tissue.
    bool fixRegion(const FixedRegion& region);

    void setTitle(const QString& title);

    // ---- Refused edits -------------------------------------------------------------------
    /// Undoes the latest edits back to the nearest earlier state on the undo stack for which
    /// `good` holds, and drops the undone edits (no redo of them is left; if the clean state
    /// was among them, the document is modified). The intermediate states are not announced:
    /// the signals fire once, for the parts that differ. False, and nothing changes, if no
    /// earlier state is good.
    bool revertTo(const std::function<bool(const Scenario&)>& good);

signals:
    /// Any edit, undo or redo, and a newly loaded document.
    void changed();
    void cutSettingsChanged();
    void strokesChanged();
    void sweepsChanged();
    void effectsChanged();
    void metadataChanged();
    /// The first tissue's fixed regions changed.
    void fixedRegionsChanged();
    /// A different document was loaded (new, open, recover, close): views rebuild.
    void documentReset();
    void fileChanged(const QString& path);
    void modifiedChanged(bool modified);
    void recentFilesChanged();

private:
    friend class ScenarioCommand;

    /// Pushes the change of the first tissue's regions to `after` (`mergeKey` >= 0: merges
    /// with the previous change of the same key).
    void pushFixedRegions(std::vector<FixedRegion> after, int mergeKey);

    /// Called by commands after they changed `parts` of m_scenario.
    void notify(unsigned parts);
    /// Replaces the whole document (not undoable): clears the undo stack, sets the file.
    void reset(Scenario scenario, const QString& filePath, bool modified);
    void setFilePath(const QString& path);
    /// A new, unsaved scenario on `tissue` with the default tool and the deformation effect.
    static Scenario newScenario(TissueSpec tissue);
    void removeOwnAutosave();
    void pushCutSettings(const CutSettings& after, int field);
    QSettings& settings() const;

    Scenario m_scenario;
    QUndoStack m_undo;
    QString m_filePath;
    QSettings* m_settings = nullptr;
    mutable std::unique_ptr<QSettings> m_appSettings; ///< created on demand
    QString m_autosaveDir;
    QTimer m_autosaveTimer;
    bool m_ownsAutosave = false; ///< this document wrote (or recovered) the autosave
    /// Parameters of effects switched off, to restore when switched on again.
    QJsonObject m_offEffectParameters;
    std::function<QString()> m_saveCheck;
    bool m_quiet = false;      ///< revertTo() is searching: notify() only collects parts
    unsigned m_quietParts = 0; ///< the parts changed while quiet
};

} // namespace resect
