#include "runner/plan/keyword_expression.h"

#include <algorithm>
#include <cctype>

namespace robottestingframework {
namespace runner {

namespace {

std::string lowered(const std::string& text) {
    std::string out = text;
    for (char& c : out) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

struct Token {
    enum class Kind { Name, And, Or, Not, Open, Close, End } kind;
    std::string text;
    std::size_t column;  // 1-based
};

bool separates(char c) {
    return c == '(' || c == ')' || std::isspace(static_cast<unsigned char>(c));
}

std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> tokens;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (c == '(' || c == ')') {
            tokens.push_back({c == '(' ? Token::Kind::Open : Token::Kind::Close, {c}, i + 1});
            ++i;
        } else {
            const std::size_t start = i;
            while (i < text.size() && !separates(text[i])) {
                ++i;
            }
            std::string word = text.substr(start, i - start);
            const Token::Kind kind = word == "and"   ? Token::Kind::And
                                     : word == "or"  ? Token::Kind::Or
                                     : word == "not" ? Token::Kind::Not
                                                     : Token::Kind::Name;
            tokens.push_back({kind, std::move(word), start + 1});
        }
    }
    tokens.push_back({Token::Kind::End, "", text.size() + 1});
    return tokens;
}

std::string described(const Token& token) {
    switch (token.kind) {
        case Token::Kind::End:
            return "the end";
        case Token::Kind::Name:
            return "the name '" + token.text + "'";
        default:
            return "'" + token.text + "'";
    }
}

}  // namespace

struct KeywordExpression::Node {
    Token::Kind kind = Token::Kind::Name;
    std::string name;  // lower case
    std::unique_ptr<Node> left;
    std::unique_ptr<Node> right;  // null for `not`

    bool matches(const std::string& id, const std::vector<std::string>& tags) const {
        switch (kind) {
            case Token::Kind::Name:
                return id.find(name) != std::string::npos ||
                       std::any_of(tags.begin(), tags.end(), [this](const std::string& tag) {
                           return tag.find(name) != std::string::npos;
                       });
            case Token::Kind::And:
                return left->matches(id, tags) && right->matches(id, tags);
            case Token::Kind::Or:
                return left->matches(id, tags) || right->matches(id, tags);
            case Token::Kind::Not:
                return !left->matches(id, tags);
            default:
                return false;
        }
    }
};

namespace {

using Node = KeywordExpression::Node;

// expression := and-expression ('or' and-expression)*
// and-expression := not-expression ('and' not-expression)*
// not-expression := 'not' not-expression | '(' expression ')' | name
class Parser {
public:
    explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

    std::unique_ptr<Node> whole() {
        auto root = expression();
        if (current().kind != Token::Kind::End) {
            fail("'and', 'or' or the end");
        }
        return root;
    }

private:
    const Token& current() const { return tokens_[next_]; }

    [[noreturn]] void fail(const std::string& expected) const {
        throw "at column " + std::to_string(current().column) + ": expected " + expected +
            "; got " + described(current());
    }

    std::unique_ptr<Node> binary(Token::Kind kind, std::unique_ptr<Node> (Parser::*operand)()) {
        auto left = (this->*operand)();
        while (current().kind == kind) {
            ++next_;
            auto node = std::make_unique<Node>();
            node->kind = kind;
            node->left = std::move(left);
            node->right = (this->*operand)();
            left = std::move(node);
        }
        return left;
    }

    std::unique_ptr<Node> expression() { return binary(Token::Kind::Or, &Parser::andExpression); }
    std::unique_ptr<Node> andExpression() {
        return binary(Token::Kind::And, &Parser::notExpression);
    }

    std::unique_ptr<Node> notExpression() {
        const Token& token = current();
        if (token.kind == Token::Kind::Not) {
            ++next_;
            auto node = std::make_unique<Node>();
            node->kind = Token::Kind::Not;
            node->left = notExpression();
            return node;
        }
        if (token.kind == Token::Kind::Open) {
            ++next_;
            auto inner = expression();
            if (current().kind != Token::Kind::Close) {
                fail("')' (for the '(' at column " + std::to_string(token.column) + ")");
            }
            ++next_;
            return inner;
        }
        if (token.kind != Token::Kind::Name) {
            fail("a name, 'not' or '('");
        }
        ++next_;
        auto node = std::make_unique<Node>();
        node->name = lowered(token.text);
        return node;
    }

    std::vector<Token> tokens_;
    std::size_t next_ = 0;
};

}  // namespace

KeywordExpression::KeywordExpression() = default;
KeywordExpression::~KeywordExpression() = default;
KeywordExpression::KeywordExpression(KeywordExpression&&) noexcept = default;
KeywordExpression& KeywordExpression::operator=(KeywordExpression&&) noexcept = default;

bool KeywordExpression::parse(const std::string& text, KeywordExpression& expression,
                              std::string& error) {
    Parser parser(tokenize(text));
    try {
        expression.root_ = parser.whole();
    } catch (const std::string& problem) {
        error = problem + " (e.g. -k 'speed and not slow', -k '(arm or leg) and grip')";
        return false;
    }
    expression.text_ = text;
    return true;
}

bool KeywordExpression::matches(const std::string& id, const std::vector<std::string>& tags) const {
    if (!root_) {
        return false;
    }
    std::vector<std::string> lowTags;
    lowTags.reserve(tags.size());
    for (const auto& tag : tags) {
        lowTags.push_back(lowered(tag));
    }
    return root_->matches(lowered(id), lowTags);
}

}  // namespace runner
}  // namespace robottestingframework
