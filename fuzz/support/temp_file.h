#pragma once
// For fuzz targets whose API takes a path (images, fonts, the settings file): the input is written to
// a file in a folder private to the process, removed at exit.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace vitrine::fuzz {

// The process's folder: a fresh mkdtemp under $TMPDIR (else /tmp), created on first use.
const std::filesystem::path& tempFolder();

// Writes the bytes to tempFolder()/name, replacing what was there, and returns the path.
std::filesystem::path writeTempFile(std::string_view name, const uint8_t* data, size_t size);

// Removes everything in tempFolder() (what the code under test left beside the input: a renamed file).
void clearTempFolder();

}  // namespace vitrine::fuzz
