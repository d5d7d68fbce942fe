#include "CommandErrors.h"

#include "CommandLine.h"

#include <exception>
#include <iostream>
#include <stdexcept>

namespace ptview {

int reportCommandError() {
    try {
        throw;
    } catch (const std::invalid_argument& e) {
        std::cerr << "ptview: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "ptview: " << e.what() << "\n";
        return kExitRuntimeError;
    }
}

} // namespace ptview
