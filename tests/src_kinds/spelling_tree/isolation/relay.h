// Spells a kind in full.
inline bool ends(ResultEvent::Kind kind) {
    return kind == ResultEvent::Kind::EndTest;
}
