#!/usr/bin/env bash
# Port check: which functions of a Box2D v3 source tree's public headers Tumble has under the
# tb prefix (b2Foo → tbFoo), and which it lacks. Usage: scripts/port-check.sh /path/to/box2d
# (a checkout of github.com/erincatto/box2d). Prints counts, the missing names and, with python3,
# the shared functions whose signatures differ.
set -euo pipefail
box2d="${1:?usage: scripts/port-check.sh /path/to/box2d}"
here="$(cd "$(dirname "$0")/.." && pwd)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grep -ohE "B2_(API|INLINE) [^;(]*\bb2[A-Za-z0-9_]+\s*\(" "$box2d"/include/box2d/*.h |
	grep -oE "b2[A-Za-z0-9_]+\s*\($" | tr -d '( ' | sed 's/^b2/tb/' | sort -u >"$tmp/v3"
grep -ohE "TB_(API|INLINE) [^;(]*\btb[A-Za-z0-9_]+\s*\(" "$here"/include/tumble/*.h |
	grep -oE "tb[A-Za-z0-9_]+\s*\($" | tr -d '( ' | sort -u >"$tmp/tb"
echo "Box2D v3 functions: $(wc -l <"$tmp/v3"); in Tumble as tb*: $(comm -12 "$tmp/v3" "$tmp/tb" | wc -l)"
echo "missing:"
comm -23 "$tmp/v3" "$tmp/tb" | sed 's/^/  /'
# Functions both have whose parameter lists differ (types only, names ignored; `const` on a value
# parameter and on a pointer Tumble only reads are harmless), and differing return types.
if command -v python3 >/dev/null; then
	python3 - "$box2d" "$here" <<'PY'
import glob, re, sys
def prototypes(pattern, api, prefix):
    found = {}
    for path in glob.glob(pattern):
        text = re.sub(r'//[^\n]*|/\*.*?\*/', '', open(path).read(), flags=re.S)
        for m in re.finditer(api + r'\s+([^;{]*?)\b(' + prefix + r'[A-Za-z0-9_]+)\s*\(([^)]*)\)', text):
            params = []
            for p in m.group(3).split(','):
                p = ' '.join(p.split())
                if p in ('', 'void'):
                    continue
                if not p.endswith('*'):
                    p = re.sub(r'\s*\b[A-Za-z_][A-Za-z0-9_]*$', '', p)
                params.append(p.replace(' *', '*'))
            found[m.group(2)] = (' '.join(m.group(1).split()), params)
    return found
rename = lambda t: re.sub(r'\bB2_', 'TB_', re.sub(r'\bb2', 'tb', t))
v3 = prototypes(sys.argv[1] + '/include/box2d/*.h', r'B2_(?:API|INLINE)', 'b2')
tb = prototypes(sys.argv[2] + '/include/tumble/*.h', r'TB_(?:API|INLINE)', 'tb')
print('signatures that differ:')
for name, (ret, params) in sorted(v3.items()):
    mine = tb.get(rename(name))
    if mine is None:
        continue
    params = [rename(p) for p in params]
    if params != mine[1]:
        print('  %s: v3 (%s), Tumble (%s)' % (rename(name), ', '.join(params), ', '.join(mine[1])))
    elif rename(ret) != mine[0] and not (ret == 'void' and mine[0] == 'bool'):
        print('  %s: returns %s in v3, %s in Tumble' % (rename(name), rename(ret), mine[0]))
PY
fi
