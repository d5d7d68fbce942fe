#pragma once
// Executes a `--script` (ViewerScript.h) in the running viewer, a few commands per frame: each
// command does what the matching UI control does, through the same model and session actions,
// so a script exercises the real program. Commands that wait (frames, wait-spp, wait-reload)
// let frames go by.

#include <ptview/window/Panels.h>
#include <ptview/model/ViewerScript.h>
#include <ptview/session/ViewerSession.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

class ScriptRunner {
public:
    explicit ScriptRunner(ViewerScript script) : script_(std::move(script)) {}

    // Runs commands until one has to wait or the script ends; once per frame, before the
    // session's update. A failing command (an unknown material, an unwritable file) ends the
    // script with exitCode() 2 and the message on stderr, "FILE:LINE: verb: reason".
    void step(ViewerSession& session, PanelState& panels);
    // After each displayed frame.
    void frameDisplayed() { ++framesDisplayed_; }

    // A `screenshot-window` path waiting for this frame's pixels, panels included; taken once.
    std::optional<std::filesystem::path> takeWindowScreenshot();
    bool quitRequested() const { return quit_; }
    int exitCode() const { return exitCode_; }

    // The verbs that have a handler (ScriptRunner.cpp, one per command): the same as the script
    // table's, viewerScriptVerbs() (ScriptRunner.EveryCommandOfTheScriptTableHasAHandler).
    static std::vector<std::string> handledVerbs();

    // One command being run: what its handler reads and changes (defined in ScriptRunner.cpp).
    struct Step;

private:
    using Clock = std::chrono::steady_clock;
    // What a command that waits waits for.
    struct Wait {
        long long untilFrame = 0;
        int reloadCount = 0; // at the start of the wait
        Clock::time_point deadline{};
    };

    // Returns false when the command must wait (and is to be run again next frame).
    bool run(const ScriptCommand& command, ViewerSession& session, PanelState& panels);
    void fail(const ScriptCommand& command, const std::string& reason);
    // "ptview: FILE:LINE: verb: discarded unsaved edits (materials, camera)" on stderr, if any.
    void noteDiscardedEdits(const ScriptCommand& command, const std::vector<std::string>& edits) const;

    ViewerScript script_;
    size_t next_ = 0;
    bool quit_ = false;
    int exitCode_ = 0;
    long long framesDisplayed_ = 0;
    // The command waiting, and what it waits for.
    bool waiting_ = false;
    Wait wait_;
    std::optional<std::filesystem::path> windowScreenshot_;
};

} // namespace ptview
