#pragma once
// Nothing the user made is lost without asking. Quitting, opening another scene and the Reload
// button replace the scene in memory; when it has unsaved edits (ViewerSession::unsavedEdits)
// the action waits here for the user's answer, which the viewer asks in a modal: Save (write the
// edits to the save target, then go on), Discard (go on without them) or Cancel (do nothing).
// Plain C++, so the rules are tested headless; the dialog only draws the question.

#include <ptview/session/ViewerSession.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ptview {

class UnsavedEditsPrompt {
public:
    enum class Action { Quit, OpenScene, Reload };
    enum class Answer { Save, Discard, Cancel };

    // Carries the action out at once when nothing would be lost (quitting then sets
    // quitConfirmed), otherwise keeps it until answer(). `scene` is the file OpenScene opens. A
    // request while another waits replaces it.
    void request(ViewerSession& session, Action action, const std::filesystem::path& scene = {});
    // The action waiting for an answer, if any.
    std::optional<Action> pending() const { return pending_; }
    const std::filesystem::path& sceneToOpen() const { return sceneToOpen_; }
    // The kinds of edits at stake (ViewerSession::unsavedEdits), as they were when asked.
    const std::vector<std::string>& edits() const { return edits_; }
    // Save writes to session.saveTarget(); when that fails (no target, a file that cannot be
    // written) the question stays open with saveError() saying why, and nothing else happens.
    void answer(ViewerSession& session, Answer answer);
    const std::string& saveError() const { return saveError_; }
    // The viewer may close: asked to, with nothing to lose or the user's answer given.
    bool quitConfirmed() const { return quitConfirmed_; }

private:
    void carryOut(ViewerSession& session, Action action, const std::filesystem::path& scene);

    std::optional<Action> pending_;
    std::filesystem::path sceneToOpen_;
    std::vector<std::string> edits_;
    std::string saveError_;
    bool quitConfirmed_ = false;
};

// "quit", "open", "reload": for status lines and messages.
const char* actionName(UnsavedEditsPrompt::Action action);

} // namespace ptview
