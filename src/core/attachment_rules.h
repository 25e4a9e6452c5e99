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

// The steps of storing one attachment that every platform takes, in this order, around its own
// calls (open, lock, create, copy). Each step that can fail returns false with the error given
// to the constructor set ("cannot attach 'SOURCE': why"); fail() does so for the platform's own.
class AttachmentSteps {
public:
    AttachmentSteps(const std::string& source, std::string& error);

    // The limits from the environment.
    bool readLimits();
    // A file of `size` bytes fits the file limit, and the run's folder is there.
    bool admitFile(std::uint64_t size);
    // `size` more bytes fit the run's limit beside what the folder holds (the folder locked).
    bool admitRun(std::uint64_t size);
    // The path of the next name to try for the copy (the one after the folder's files, then
    // the next if that one was taken meanwhile).
    std::filesystem::path nextStored();
    // Removes the copy being made, after a failure.
    void discardStored();
    // Fills `attachment` for the copy made, of `size` bytes.
    void describe(const std::string& description, std::uint64_t size, Attachment& attachment);

    // Sets the error to this attachment's one with `why`; returns false.
    bool fail(const std::string& why);

    const std::string& source() const { return source_; }
    const std::filesystem::path& folder() const { return folder_; }
    std::uint64_t fileLimit() const { return fileLimit_; }

private:
    const std::string& source_;
    std::string& error_;
    std::uint64_t fileLimit_ = 0;
    std::uint64_t runLimit_ = 0;
    std::filesystem::path folder_;
    std::uint64_t files_ = 0;  // in the folder, when the run's limit was last checked
    std::uint64_t tried_ = 0;  // names tried for the copy
    std::string storedName_;
};

// What storeAttachment() does after reading the limits, with the platform's calls
// (attachment_store-<platform>.cpp): opens the source, takes the folder's lock, copies it in.
bool storeCopy(AttachmentSteps& steps, const std::string& description, Attachment& attachment);

}  // namespace robottestingframework
