#include <ptview/session/UnsavedEditsPrompt.h>

#include <exception>

namespace ptview {

const char* actionName(UnsavedEditsPrompt::Action action) {
    switch (action) {
    case UnsavedEditsPrompt::Action::Quit: return "quit";
    case UnsavedEditsPrompt::Action::OpenScene: return "open";
    case UnsavedEditsPrompt::Action::Reload: return "reload";
    }
    return "";
}

void UnsavedEditsPrompt::request(ViewerSession& session, Action action, const std::filesystem::path& scene) {
    saveError_.clear();
    edits_ = session.unsavedEdits();
    if (edits_.empty()) {
        pending_.reset();
        carryOut(session, action, scene);
        return;
    }
    pending_ = action;
    sceneToOpen_ = scene;
}

void UnsavedEditsPrompt::answer(ViewerSession& session, Answer answer) {
    if (!pending_) return;
    if (answer == Answer::Cancel) {
        pending_.reset();
        saveError_.clear();
        return;
    }
    if (answer == Answer::Save) {
        if (session.saveTarget().empty()) {
            saveError_ = "no file to save to: type one in Materials > Save scene as";
            return;
        }
        try {
            session.saveSceneAs(session.saveTarget());
        } catch (const std::exception& e) { // names the file
            saveError_ = e.what();
            return;
        }
    }
    Action action = *pending_;
    pending_.reset();
    saveError_.clear();
    carryOut(session, action, sceneToOpen_);
}

void UnsavedEditsPrompt::carryOut(ViewerSession& session, Action action, const std::filesystem::path& scene) {
    switch (action) {
    case Action::Quit: quitConfirmed_ = true; break;
    case Action::OpenScene: session.openScene(scene); break; // a file that does not load keeps everything
    case Action::Reload:
        // With edits discarded the file is read as it is; otherwise (none, or just saved) the
        // merge keeps the scene in memory and takes what the file changed.
        if (session.hasUnsavedEdits())
            session.openScene(session.model().fileScene.path);
        else
            session.reloadScene();
        break;
    }
}

} // namespace ptview
