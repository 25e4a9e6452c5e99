# private-apt.sh, sourced: `private_apt DIR KIND` sets up an apt configuration of its own under
# DIR (its sources.list with Debian 12's lines of KIND, deb-src for source packages or deb for
# binary ones, its lists and caches) and fills the array private_apt_options with the options
# that make apt-get use it. The machine's /etc/apt and /var/lib/apt are never written. Used by
# the scripts that fetch Debian's source packages (windows-deps.sh, rtf2-tests.sh) and binary
# packages (rtf2-binaries.sh) into a build tree.
private_apt() {
    local dir=$1 kind=$2
    mkdir -p "$dir/lists/partial" "$dir/cache/archives/partial" "$dir/sources.list.d"
    cat >"$dir/sources.list" <<LIST
$kind [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main
$kind [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm-updates main
LIST
    private_apt_options=(
        -o "Dir::Etc::sourcelist=$dir/sources.list"
        -o "Dir::Etc::sourceparts=$dir/sources.list.d"
        -o "Dir::State::Lists=$dir/lists"
        -o "Dir::Cache=$dir/cache"
        -o "Dir::Cache::archives=$dir/cache/archives"
        -o "Dir::Cache::pkgcache=$dir/cache/pkgcache.bin"
        -o "Dir::Cache::srcpkgcache=$dir/cache/srcpkgcache.bin"
        -o "Debug::NoLocking=1"
        -o "APT::Sandbox::User=root"
    )
}
