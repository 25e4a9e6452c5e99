// Where testAttach puts files: the run's attachments folder, beside the report outputs. The
// runner names it (RTF_ATTACHMENTS_DIR, inherited by its workers); without a runner it is
// ./rtf-attachments. Bounded per file and per run (docs/how-to/measurements-and-attachments.md),
// across every process of the run: the folder itself is the account, read under a lock.
#pragma once

#include <cstdint>
#include <string>

#include <robottestingframework/Attachment.h>

namespace robottestingframework {

constexpr const char* kAttachmentsFolderVariable = "RTF_ATTACHMENTS_DIR";
constexpr const char* kAttachmentFileLimitVariable = "RTF_ATTACHMENT_MAX_FILE";
constexpr const char* kAttachmentRunLimitVariable = "RTF_ATTACHMENT_MAX_RUN";
constexpr std::uint64_t kDefaultAttachmentFileLimit = 16ull * 1024 * 1024;
constexpr std::uint64_t kDefaultAttachmentRunLimit = 256ull * 1024 * 1024;

// Copies `source` into the attachments folder and fills `attachment`; false with `error`
// (naming the file and the limit) when it cannot.
bool storeAttachment(const std::string& source, const std::string& description,
                     Attachment& attachment, std::string& error);

}  // namespace robottestingframework
