#!/usr/bin/env bash
# Builds the documentation site (./run.sh docs; ctest docs.site): the C++ API reference from
# the public headers with Doxygen (Doxyfile; warnings are errors), then the pages of docs/ with
# mkdocs in strict mode (mkdocs.yml; a broken link between pages fails), then every internal
# link of README.md, docs/ and the built site (scripts/check-doc-links.py).
#   scripts/build-docs.sh [BUILD_DIR]   the site in BUILD_DIR/docs/site (default build)
# Fails (exit 1) when doxygen or mkdocs is missing, saying how to get them.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
mkdir -p "${1:-build}"
out=$(cd "${1:-build}" && pwd)/docs
for tool in doxygen mkdocs; do
    command -v $tool >/dev/null || {
        echo "build-docs: $tool is missing (Debian: apt-get install $tool; ./run.sh docs and" \
            "./run.sh test install it: scripts/install-deps.sh --docs)" >&2
        exit 1
    }
done
rm -rf "$out"
mkdir -p "$out/src"
cp -r docs/. "$out/src/"
rm -rf "$out/src/new"
# Doxygen writes into the pages' copy (api/), so mkdocs copies it into the site and checks
# the pages' links to it.
(cat Doxyfile; echo "OUTPUT_DIRECTORY = $out/src/api") | doxygen -
cat > "$out/mkdocs.yml" <<YAML
INHERIT: $root/mkdocs.yml
docs_dir: src
site_dir: site
YAML
mkdocs build --strict --quiet --config-file "$out/mkdocs.yml"
python3 scripts/check-doc-links.py "$root" --site "$out/site"
echo "build-docs: the site is in $out/site/index.html"
