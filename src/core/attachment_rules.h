// The rules of the attachments folder that every platform shares (attachment_store.cpp): its
// limits, where it is, what it holds, and how a stored file is described. The platform files
// (attachment_store-<platform>.cpp) open, lock and copy with their own calls around them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <robottestingframework/Attachment.h>

namespace robottestingframework {

// The per-file and per-run limits from the environment (defaults when unset); false with
// `error` when one is set to anything but a whole number of bytes.
bool attachmentLimits(std::uint64_t& fileLimit, std::uint64_t& runLimit, std::string& error);

// Empty when a file of `size` bytes fits `fileLimit`, else why not.
std::string fileOverLimit(std::uint64_t size, std::uint64_t fileLimit);

// The run's folder (RTF_ATTACHMENTS_DIR, else ./rtf-attachments), made if missing; false with
// `error` when it cannot be.
bool attachmentsFolder(std::filesystem::path& folder, std::string& error);

// Empty when `size` more bytes fit the run's limit beside what `folder` holds already, else
// why not; `files` gets how many files it holds (the next stored file's number follows it).
std::string runOverLimit(const std::filesystem::path& folder, std::uint64_t size,
                         std::uint64_t runLimit, std::uint64_t& files);

// The name a stored copy of `source` gets in its folder: "<number>-<safe file name>".
std::string storedNameOf(const std::string& source, std::uint64_t number);

// Fills `attachment` for the copy `storedName` in `folder` of `source`.
void describeStored(const std::filesystem::path& folder, const std::string& storedName,
                    const std::string& source, const std::string& description, std::uint64_t size,
                    Attachment& attachment);

}  // namespace robottestingframework
