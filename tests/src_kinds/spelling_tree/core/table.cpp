// Spells a kind through an alias, as a table does.
using Kind = ResultEvent::Kind;
constexpr Kind first = Kind::StartRunner;
