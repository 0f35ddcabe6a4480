# Sourced by scripts/fetch-glslang-tests and scripts/fetch-glslang-source: the source package of
# the installed glslang from the Debian archive, the way a user would fetch it (its .dsc, then the
# orig tarball and Debian's .diff.gz checked against the SHA-256 sums the .dsc lists).
#
# glslang_source_init NAME      sets $version (GLSLANG_VERSION or the installed glslang-dev's),
#                               $pool and $stamp; exits when neither is known.
# glslang_fetch_verified TMP KIND  downloads the .dsc (once) and the member of kind `orig` or
#                               `diff` into TMP; sets $tarball (its file name) and $sha256.

glslang_source_init() {
  local name=$1
  archive=${DEBIAN_ARCHIVE:-http://deb.debian.org/debian}
  version=${GLSLANG_VERSION:-$(dpkg-query -W -f='${source:Version}' glslang-dev 2>/dev/null || true)}
  if [ -z "$version" ]; then
    echo "$name: glslang-dev is not installed; set GLSLANG_VERSION (e.g. 12.0.0-2)" >&2
    exit 1
  fi
  pool=$archive/pool/main/g/glslang
  stamp="debian-source: glslang $version"
  glslang_source_name=$name
}

glslang_fetch_verified() {
  local tmp=$1 kind=$2 pattern
  local dsc=glslang_${version#*:}.dsc
  if [ ! -f "$tmp/glslang.dsc" ]; then
    echo "$glslang_source_name: $pool/$dsc"
    curl -fsSL -o "$tmp/glslang.dsc" "$pool/${dsc//+/%2B}"
  fi
  case $kind in
    orig) pattern='\.orig\.tar\.' ;;
    diff) pattern='\.(diff\.gz|debian\.tar\.[a-z]+)$' ;;
  esac
  # The member's name and SHA-256 from the .dsc's Checksums-Sha256 section.
  sha256='' tarball=''
  read -r sha256 _ tarball < <(awk -v re="$pattern" '/^Checksums-Sha256:/ {on = 1; next} /^[^ ]/ {on = 0}
                                    on && $3 ~ re {print $1, $2, $3; exit}' "$tmp/glslang.dsc") || true
  if [ -z "$tarball" ]; then
    echo "$glslang_source_name: no $kind member listed in $dsc" >&2
    return 1
  fi
  echo "$glslang_source_name: $pool/$tarball"
  curl -fsSL -o "$tmp/$tarball" "$pool/${tarball//+/%2B}"
  echo "$sha256  $tmp/$tarball" | sha256sum -c --quiet -
}
