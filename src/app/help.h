#pragma once
// The documents made from the flag table (app/flags.h): --help, the man page and the bash completion
// script. The binary prints the last two itself (--help-man, --help-completion), so a package build
// runs the program it has just built and needs no second tool that could describe other flags; the
// build makes both beside the binary (the vitrine_docs target).
#include <string>

namespace vitrine::help {

std::string usage();           // --help: the synopsis of each mode, then every flag, at most 100 columns
std::string manPage();         // man(7) roff for section 1
std::string bashCompletion();  // a script for bash's `complete`

}  // namespace vitrine::help
