#include <robottestingframework/Attachment.h>

#include <algorithm>
#include <cctype>

namespace robottestingframework {

std::string Attachment::contentType() const {
    // The types a report can show inline or a browser opens as text; the rest is downloaded.
    static const struct {
        const char* extension;
        const char* type;
    } types[] = {
        {".png", "image/png"},       {".jpg", "image/jpeg"}, {".jpeg", "image/jpeg"},
        {".svg", "image/svg+xml"},   {".gif", "image/gif"},  {".txt", "text/plain"},
        {".log", "text/plain"},      {".csv", "text/csv"},   {".json", "application/json"},
        {".xml", "application/xml"}, {".html", "text/html"}, {".pdf", "application/pdf"},
    };
    std::string name = originalName.empty() ? path : originalName;
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const auto& entry : types) {
        const std::string extension = entry.extension;
        if (name.size() >= extension.size() &&
            name.compare(name.size() - extension.size(), extension.size(), extension) == 0) {
            return entry.type;
        }
    }
    return "application/octet-stream";
}

std::string describeAttachment(const Attachment& attachment) {
    return attachment.path +
           (attachment.description.empty() ? std::string() : " (" + attachment.description + ")");
}

}  // namespace robottestingframework
