#include <ptview/commands/CommandErrors.h>

#include <ptview/commands/CommandLine.h>
#include <ptview/io/PrintableText.h>

#include <exception>
#include <iostream>
#include <stdexcept>

namespace ptview {

int reportCommandError() {
    try {
        throw;
    } catch (const std::invalid_argument& e) {
        printMessage(e.what());
        return kExitBadInput;
    } catch (const std::exception& e) {
        printMessage(e.what());
        return kExitRuntimeError;
    }
}

} // namespace ptview
