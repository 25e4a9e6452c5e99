// Spells a kind at the start of a line.
const auto kind = Kind::Probe;
