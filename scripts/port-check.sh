#!/usr/bin/env bash
# Port check: which functions of a Box2D v3 source tree's public headers Tumble has under the
# tb prefix (b2Foo → tbFoo), and which it lacks. Usage: scripts/port-check.sh /path/to/box2d
# (a checkout of github.com/erincatto/box2d). Prints counts, the missing names and, with python3,
# the shared functions whose signatures differ; then, with python3, the same for every public
# typedef, every struct field (name and type) and every enum value (name and value), each renamed
# b2 → tb and B2_ → TB_, with the fields and values Tumble has beyond v3 listed as extensions.
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
	# Typedefs, struct fields and enum values. The headers are read as the preprocessor would for
	# the default (float) build, then again for the large-world build with v3's and Tumble's
	# double-precision macros defined; items that differ only there are listed apart. A typedef
	# compares by what it names (a function typedef by its return and parameter types, names
	# ignored); struct and enum typedefs by their members below. Anonymous unions count their
	# members as fields of the struct, as C lets a program name them so.
	python3 - "$box2d" "$here" <<'PY'
import glob, re, sys

def strip_comments(text):
    return re.sub(r'//[^\n]*|/\*.*?\*/', '', text, flags=re.S)

def preprocess(text, defined):
    # Keeps the lines of the branches taken when exactly the macros in `defined` are defined.
    out, stack = [], []
    def cond(expr):
        expr = re.sub(r'defined\s*\(\s*(\w+)\s*\)|defined\s+(\w+)',
                      lambda m: ' 1 ' if (m.group(1) or m.group(2)) in defined else ' 0 ', expr)
        expr = expr.replace('&&', ' and ').replace('||', ' or ')
        expr = re.sub(r'!(?!=)', ' not ', expr)
        expr = re.sub(r'\b[A-Za-z_]\w*\b', lambda m: m.group(0) if m.group(0) in ('and', 'or', 'not') else '0', expr)
        try:
            return bool(eval(expr, {}, {}))
        except Exception:
            return False
    for line in text.split('\n'):
        s = line.strip()
        m = re.match(r'#\s*(ifdef|ifndef|if|elif|else|endif)\b(.*)', s)
        if not m:
            if all(st[0] for st in stack):
                out.append(line)
            continue
        kw, rest = m.group(1), m.group(2).strip()
        if kw in ('ifdef', 'ifndef', 'if'):
            v = (rest in defined) if kw == 'ifdef' else (rest not in defined) if kw == 'ifndef' else cond(rest)
            stack.append([v, v])
        elif kw == 'elif':
            st = stack[-1]
            v = (not st[1]) and cond(rest)
            st[0] = v
            st[1] = st[1] or v
        elif kw == 'else':
            st = stack[-1]
            st[0] = not st[1]
            st[1] = True
        else:
            stack.pop()
    return '\n'.join(out)

def norm_type(t):
    t = ' '.join(t.split())
    t = re.sub(r'\s*\*\s*', '* ', t).strip()
    t = re.sub(r'\*\s+(?=\*|\)|\]|,|$)', '*', t)
    t = re.sub(r'\(\s+', '(', t)
    t = re.sub(r'\s+\)', ')', t)
    return t.strip()

def norm_params(params):
    out = []
    for p in params.split(','):
        p = ' '.join(p.split())
        if p in ('', 'void'):
            continue
        if not p.endswith('*'):
            p = re.sub(r'\s*\b[A-Za-z_][A-Za-z0-9_]*$', '', p)
        out.append(norm_type(p))
    return out

def split_top(body, sep):
    parts, depth, cur = [], 0, ''
    for ch in body:
        if ch in '({[':
            depth += 1
        elif ch in ')}]':
            depth -= 1
        if ch == sep and depth == 0:
            parts.append(cur)
            cur = ''
        else:
            cur += ch
    if cur.strip():
        parts.append(cur)
    return parts

def fields_of(body):
    fields = []
    for decl in split_top(body, ';'):
        decl = ' '.join(decl.split())
        if not decl:
            continue
        m = re.match(r'^(?:union|struct)\s*\{(.*)\}\s*(\w*)$', decl)
        if m:
            inner = fields_of(m.group(1))
            if m.group(2):
                fields.append((m.group(2), '{' + '; '.join(t + ' ' + n for n, t in inner) + '}'))
            else:
                fields.extend(inner)
            continue
        m = re.match(r'^(.*?)\(\s*\*\s*(\w+)\s*\)\s*\((.*)\)$', decl)
        if m:
            fields.append((m.group(2), norm_type(m.group(1)) + '(*)(' + ', '.join(norm_params(m.group(3))) + ')'))
            continue
        m = re.match(r'^(.*?[\s*])(\w+(?:\s*\[[^\]]*\])?(?:\s*,\s*\**\s*\w+(?:\s*\[[^\]]*\])?)*)$', decl)
        if not m:
            continue
        base = m.group(1)
        for name in m.group(2).split(','):
            name = name.strip()
            stars = len(name) - len(name.lstrip('*'))
            name = name.lstrip('* ')
            arr = ''
            a = re.match(r'(\w+)\s*(\[.*\])', name)
            if a:
                name, arr = a.group(1), a.group(2).replace(' ', '')
            fields.append((name, norm_type(base + '*' * stars) + arr))
    return fields

def parse(pattern, prefix, defined):
    structs, enums, typedefs = {}, {}, {}
    for path in sorted(glob.glob(pattern)):
        text = preprocess(strip_comments(open(path).read()), defined)
        i = 0
        for m in re.finditer(r'\btypedef\b', text):
            start = m.end()
            # struct / enum / union with a body
            sm = re.match(r'\s*(struct|enum|union)\s*(\w*)\s*\{', text[start:])
            if sm:
                j = start + sm.end()
                depth = 1
                while depth:
                    if text[j] == '{':
                        depth += 1
                    elif text[j] == '}':
                        depth -= 1
                    j += 1
                body = text[start + sm.end():j - 1]
                nm = re.match(r'\s*(\w+)\s*;', text[j:])
                if not nm:
                    continue
                name = nm.group(1)
                if sm.group(1) == 'enum':
                    values, counter = [], 0
                    for item in split_top(body, ','):
                        item = ' '.join(item.split())
                        if not item:
                            continue
                        if '=' in item:
                            k, v = [s.strip() for s in item.split('=', 1)]
                            try:
                                counter = int(v, 0)
                                val = str(counter)
                            except ValueError:
                                val = v
                                counter = None
                        else:
                            k = item
                            val = str(counter) if counter is not None else '?'
                        values.append((k, val))
                        if counter is not None:
                            counter += 1
                    enums[name] = values
                    typedefs[name] = 'enum'
                else:
                    structs[name] = fields_of(body)
                    typedefs[name] = sm.group(1)
                continue
            end = text.index(';', start)
            decl = ' '.join(text[start:end].split())
            fm = re.match(r'^(.*?)\b(\w+)\s*\((.*)\)$', decl)
            if fm and fm.group(2).startswith(prefix):
                typedefs[fm.group(2)] = norm_type(fm.group(1)) + '(' + ', '.join(norm_params(fm.group(3))) + ')'
                continue
            am = re.match(r'^(.*?)\b(\w+)$', decl)
            if am:
                typedefs[am.group(2)] = norm_type(am.group(1))
    return structs, enums, typedefs

rename = lambda t: re.sub(r'\bB2_', 'TB_', re.sub(r'\bb2', 'tb', re.sub(r'\bb2_', 'tb_', t)))

def compare(box2d, here, double):
    dv3 = {'BOX2D_DOUBLE_PRECISION'} if double else set()
    dtb = {'TUMBLE_DOUBLE_PRECISION'} if double else set()
    s3, e3, t3 = parse(box2d + '/include/box2d/*.h', 'b2', dv3)
    stb, etb, ttb = parse(here + '/include/tumble/*.h', 'tb', dtb)
    report = {}
    # typedefs
    missing_t, differ_t = [], []
    for name, kind in sorted(t3.items()):
        if not name.startswith('b2'):
            continue
        mine = ttb.get(rename(name))
        if mine is None:
            missing_t.append(rename(name))
        elif rename(kind) != mine and not (kind in ('struct', 'enum') and mine in ('struct', 'enum')):
            differ_t.append('%s: v3 %s, Tumble %s' % (rename(name), rename(kind), mine))
    nt = sum(1 for n in t3 if n.startswith('b2'))
    report['typedefs'] = (nt, nt - len(missing_t) - len(differ_t), missing_t, differ_t)
    # fields
    missing_f, differ_f, extra_f, nf = [], [], [], 0
    for name, fields in sorted(s3.items()):
        tname = rename(name)
        mine = dict(stb.get(tname, []))
        for fname, ftype in fields:
            nf += 1
            if tname not in stb:
                missing_f.append('%s.%s (%s; no struct %s)' % (tname, fname, rename(ftype), tname))
            elif fname not in mine:
                missing_f.append('%s.%s (%s)' % (tname, fname, rename(ftype)))
            elif mine[fname] != rename(ftype):
                differ_f.append('%s.%s: v3 %s, Tumble %s' % (tname, fname, rename(ftype), mine[fname]))
        if tname in stb:
            v3names = {f for f, _ in fields}
            for fname, ftype in stb[tname]:
                if fname not in v3names:
                    extra_f.append('%s.%s' % (tname, fname))
    report['fields'] = (nf, nf - len(missing_f) - len(differ_f), missing_f, differ_f, extra_f)
    # enum values
    missing_e, differ_e, extra_e, ne = [], [], [], 0
    for name, values in sorted(e3.items()):
        tname = rename(name)
        mine = dict(etb.get(tname, []))
        for k, v in values:
            ne += 1
            if rename(k) not in mine:
                missing_e.append('%s %s = %s' % (tname, rename(k), v))
            elif mine[rename(k)] != rename(v):
                differ_e.append('%s %s: v3 %s, Tumble %s' % (tname, rename(k), v, mine[rename(k)]))
        if tname in etb:
            v3names = {rename(k) for k, _ in values}
            extra_e += ['%s %s' % (tname, k) for k, _ in etb[tname] if k not in v3names]
    report['enums'] = (ne, ne - len(missing_e) - len(differ_e), missing_e, differ_e, extra_e)
    return report

box2d, here = sys.argv[1], sys.argv[2]
single = compare(box2d, here, False)
double = compare(box2d, here, True)
for key, label in (('typedefs', 'typedefs'), ('fields', 'struct fields'), ('enums', 'enum values')):
    r = single[key]
    print('Box2D v3 %s: %d; in Tumble alike: %d' % (label, r[0], r[1]))
    print('missing:')
    for item in r[2]:
        print('  ' + item)
    print('differing:')
    for item in r[3]:
        print('  ' + item)
    d = double[key]
    extra = [x for x in d[2] + d[3] if x not in r[2] + r[3]]
    if extra:
        print('only in the large-world build (BOX2D_DOUBLE_PRECISION / TUMBLE_DOUBLE_PRECISION):')
        for item in extra:
            print('  ' + item)
    if len(r) > 4 and r[4]:
        print('Tumble only (extensions): ' + ', '.join(r[4]))
PY
fi
