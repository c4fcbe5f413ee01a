#pragma once
// Capturing VTK's error and warning messages so that file readers and writers can turn
// them into a Status instead of printing them. Private to resect_scenario.
//
// VTK sends an object's message to its ErrorEvent observers if it has any; otherwise to
// vtkLogger (stderr) and to the process-wide vtkOutputWindow. A reader creates many
// objects of its own (XML elements, arrays, decompressors) that cannot be observed from
// outside, so observers alone cannot keep stderr quiet: while a capture is alive, the
// output window is replaced by one that records messages and vtkLogger's stderr output is
// switched off; both are restored when the capture ends.

#include "core/status.h"

#include <memory>
#include <string>

class vtkAlgorithm;
class vtkUnstructuredGrid;

namespace resect::detail {

/// While alive, every VTK error or warning message (from any object, any thread) is
/// recorded here instead of being printed. Captures are serialised by a process-wide
/// recursive mutex because VTK's message routing is global: messages that other threads
/// emit during a capture are recorded (and not printed) too.
class ScopedVtkMessageCapture {
public:
    ScopedVtkMessageCapture();
    ~ScopedVtkMessageCapture();
    ScopedVtkMessageCapture(const ScopedVtkMessageCapture&) = delete;
    ScopedVtkMessageCapture& operator=(const ScopedVtkMessageCapture&) = delete;

    /// Number of error messages recorded so far (warnings are recorded but not counted).
    int errorCount() const;
    /// The first error message, without VTK's "ERROR: In file, line" header and the
    /// "vtkClass (0x...): " prefix; empty if there was none.
    std::string firstError() const;

private:
    struct State;
    std::unique_ptr<State> m_state;
};

/// Runs a grid reader's pipeline with its messages captured: its output grid in `grid` if
/// the pipeline succeeded and reported no error, else "PATH: not a readable WHAT (VTK's
/// first error)". The pipeline's result is checked as well as the messages: with
/// vtkObject::GlobalWarningDisplay switched off somewhere, VTK reports nothing.
Status updateGridReader(vtkAlgorithm* reader, const std::string& path, const std::string& what,
                        vtkUnstructuredGrid*& grid);

} // namespace resect::detail
