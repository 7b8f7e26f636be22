#pragma once
// What makes a file named like a plugin unfit to be opened, found before dlopen sees it (plugin_loader.cpp). dlopen
// maps a library's segments as its program headers say, whatever the file's length: the pages of a segment past the
// end of a cut-short file (a copy or install that stopped part-way, on a full disk say) raise SIGBUS when first
// touched, in the process that opened it. And a name that is not a file (a dangling symbolic link, a directory) must
// be reported, not passed over for another folder's plugin.
#include <string>

namespace vssw::multibody {

// "" when `path` is a regular file (through any symbolic links) whose every loadable segment lies within it; else why
// not, as words that follow "could not be loaded: " ("it is a directory", "the file is cut short ..."). A file that
// is not an ELF library of this machine's class is left to dlopen, which refuses it with a reason of its own, read
// from the file without mapping it.
std::string plugin_file_problem(const std::string& path);

// The GNU build-id the linker wrote into the library at `path` (its NT_GNU_BUILD_ID note, a hash of the linked file
// that stripping keeps), as lower-case hex, read from the file without opening it as a library; "" when the file is
// not an ELF library of this machine's class or has no such note.
std::string plugin_build_note(const std::string& path);

}  // namespace vssw::multibody
