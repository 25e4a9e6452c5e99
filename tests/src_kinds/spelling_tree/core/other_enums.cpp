// Not counted: another enum's members of the same names, longer names, and the table's
// questions.
const auto ready = ReadyCheck::Kind::Output;
const auto tone = KindTone::Bad;
const auto word = Kind::Reported;
const bool said = isSaid(event);
