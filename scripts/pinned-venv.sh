# pinned-venv.sh, sourced: `pinned_venv NAME PREFIX PYTHON PIN...` makes PREFIX a virtual
# environment of its own (made by PYTHON) holding the pinned PyPI packages PIN..., unless it
# already holds exactly those (a stamp file says which); NAME starts its messages. Used by the
# scripts that install Python tooling into a build tree (python-tools.sh, bench-tools.sh):
# nothing is installed outside it, and once installed nothing is fetched again.
pinned_venv() {
    local name=$1 prefix=$2 python=$3
    shift 3
    local stamp="$prefix/installed"
    if [[ -f "$stamp" && "$(cat "$stamp")" == "$*" ]]; then
        return 0
    fi
    rm -rf "$prefix"
    if ! "$python" -m venv "$prefix"; then
        echo "$name: $python cannot make a virtual environment; run scripts/install-deps.sh" >&2
        return 1
    fi
    echo "$name: installing $* into $prefix"
    "$prefix/bin/python" -m pip install --quiet --disable-pip-version-check --no-input "$@"
    echo "$*" >"$stamp"
}
