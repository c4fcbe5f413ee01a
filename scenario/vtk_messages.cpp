#include "scenario/vtk_messages.h"

#include <vtkAlgorithm.h>
#include <vtkExecutive.h>
#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cctype>
#include <mutex>

namespace resect::detail {
namespace {

/// Longest message kept for a Status; VTK's can run to many lines.
constexpr std::size_t kMaxMessageChars = 300;

/// Strips VTK's "ERROR: In FILE, line N" header and "vtkClass (0x...): " prefix, joins
/// lines and trims.
std::string cleanMessage(std::string msg) {
    for (const char* header : {"ERROR: In ", "Warning: In ", "Generic Warning: In "})
        if (msg.rfind(header, 0) == 0) {
            const std::size_t nl = msg.find('\n');
            msg.erase(0, nl == std::string::npos ? msg.size() : nl + 1);
            break;
        }
    const std::size_t tag = msg.find("): ");
    if (tag != std::string::npos && tag < msg.find('\n'))
        msg.erase(0, tag + 3);
    for (char& c : msg)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!msg.empty() && std::isspace(static_cast<unsigned char>(msg.back())))
        msg.pop_back();
    if (msg.size() > kMaxMessageChars)
        msg = msg.substr(0, kMaxMessageChars) + "...";
    return msg;
}

/// An output window that records messages instead of displaying them.
class RecordingOutputWindow : public vtkOutputWindow {
public:
    static RecordingOutputWindow* New();

    void DisplayText(const char*) override {}
    void DisplayErrorText(const char* text) override {
        const std::lock_guard<std::mutex> lock(m_mutex); // VTK may report from worker threads
        ++m_errors;
        if (m_first.empty() && text)
            m_first = cleanMessage(text);
    }
    void DisplayWarningText(const char*) override {}
    void DisplayGenericWarningText(const char*) override {}
    void DisplayDebugText(const char*) override {}

    int errors() const {
        const std::lock_guard<std::mutex> lock(m_mutex);
        return m_errors;
    }
    std::string first() const {
        const std::lock_guard<std::mutex> lock(m_mutex);
        return m_first;
    }

private:
    RecordingOutputWindow() = default;
    mutable std::mutex m_mutex;
    int m_errors = 0;
    std::string m_first;
};
vtkStandardNewMacro(RecordingOutputWindow);

std::recursive_mutex& captureMutex() {
    static std::recursive_mutex mutex;
    return mutex;
}

} // namespace

struct ScopedVtkMessageCapture::State {
    std::unique_lock<std::recursive_mutex> lock{captureMutex()};
    vtkSmartPointer<vtkOutputWindow> previousWindow;
    vtkSmartPointer<RecordingOutputWindow> window;
    vtkLogger::Verbosity previousStderr = vtkLogger::VERBOSITY_INFO;
};

ScopedVtkMessageCapture::ScopedVtkMessageCapture() : m_state(std::make_unique<State>()) {
    // vtkLogger has no getter for the stderr verbosity, only for the highest verbosity of
    // all its outputs. With stderr off, that is the cutoff of the other outputs (files,
    // callbacks); if it dropped, stderr was the highest and its level is known exactly.
    // Otherwise stderr was at most the old cutoff; VTK's default (INFO) is restored,
    // capped at that cutoff.
    const vtkLogger::Verbosity before = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    const vtkLogger::Verbosity others = vtkLogger::GetCurrentVerbosityCutoff();
    m_state->previousStderr =
        others < before ? before : std::min(before, vtkLogger::VERBOSITY_INFO);

    m_state->previousWindow = vtkOutputWindow::GetInstance();
    m_state->window = vtkSmartPointer<RecordingOutputWindow>::New();
    vtkOutputWindow::SetInstance(m_state->window);
}

ScopedVtkMessageCapture::~ScopedVtkMessageCapture() {
    vtkOutputWindow::SetInstance(m_state->previousWindow);
    vtkLogger::SetStderrVerbosity(m_state->previousStderr);
}

int ScopedVtkMessageCapture::errorCount() const {
    return m_state->window->errors();
}

std::string ScopedVtkMessageCapture::firstError() const {
    return m_state->window->first();
}

Status updateGridReader(vtkAlgorithm* reader, const std::string& path, const std::string& what,
                        vtkUnstructuredGrid*& grid) {
    ScopedVtkMessageCapture messages;
    const bool updated = reader->GetExecutive()->Update() != 0;
    grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
    if (!updated || messages.errorCount() > 0 || !grid)
        return Status::error(path + ": not a readable " + what + " (" +
                             (messages.firstError().empty() ? std::string("unknown VTK error")
                                                            : messages.firstError()) +
                             ")");
    return Status::success();
}

} // namespace resect::detail
