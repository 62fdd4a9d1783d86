"""omniidl back end: prints every declaration as `scoped-name<TAB>field<TAB>value` lines.

Two IDL trees that declare the same types print the same lines, whatever their formatting, comments,
file split or declaration order, so the conformance test can compare ours with the reference field by
field. Parameter names are left out on purpose: they never reach the wire.
"""

from omniidl import idlast, idltype

BASE = {
    idltype.tk_void: "void", idltype.tk_short: "short", idltype.tk_long: "long",
    idltype.tk_ushort: "unsigned short", idltype.tk_ulong: "unsigned long",
    idltype.tk_float: "float", idltype.tk_double: "double", idltype.tk_boolean: "boolean",
    idltype.tk_char: "char", idltype.tk_octet: "octet", idltype.tk_any: "any",
    idltype.tk_TypeCode: "CORBA::TypeCode", idltype.tk_longlong: "long long",
    idltype.tk_ulonglong: "unsigned long long", idltype.tk_longdouble: "long double",
    idltype.tk_wchar: "wchar",
}


def type_name(t):
    if isinstance(t, idltype.Base):
        return BASE[t.kind()]
    if isinstance(t, idltype.String):
        return "string<%d>" % t.bound() if t.bound() else "string"
    if isinstance(t, idltype.WString):
        return "wstring<%d>" % t.bound() if t.bound() else "wstring"
    if isinstance(t, idltype.Sequence):
        inner = type_name(t.seqType())
        return "sequence<%s, %d>" % (inner, t.bound()) if t.bound() else "sequence<%s>" % inner
    if isinstance(t, idltype.Declared):
        return "::".join(t.scopedName())
    raise ValueError("unsupported type kind %d" % t.kind())


def label_text(value):
    return "::".join(value.scopedName()) if isinstance(value, idlast.Enumerator) else str(value)


def declarator_type(base, declarator):
    return base + "".join("[%d]" % size for size in declarator.sizes())


class Printer:
    def __init__(self):
        self.lines = set()

    def emit(self, name, field, value):
        self.lines.add("%s\t%s\t%s" % (name, field, value))

    def header(self, decl, kind):
        name = "::".join(decl.scopedName())
        self.emit(name, "kind", kind)
        self.emit(name, "repository id", decl.repoId())
        return name

    def members(self, name, members):
        index = 0
        for member in members:
            for declarator in member.declarators():
                self.emit(name, "member %d" % index,
                          "%s %s" % (declarator_type(type_name(member.memberType()), declarator),
                                     declarator.identifier()))
                index += 1
        self.emit(name, "member count", str(index))

    def declaration(self, decl):
        if isinstance(decl, idlast.Module):
            for inner in decl.definitions():
                self.declaration(inner)
        elif isinstance(decl, idlast.Interface):
            self.interface(decl)
        elif isinstance(decl, idlast.Struct):
            name = self.header(decl, "struct")
            self.members(name, decl.members())
        elif isinstance(decl, idlast.Exception):
            name = self.header(decl, "exception")
            self.members(name, decl.members())
        elif isinstance(decl, idlast.Enum):
            name = self.header(decl, "enum")
            self.emit(name, "enumerators", ", ".join(e.identifier() for e in decl.enumerators()))
        elif isinstance(decl, idlast.Typedef):
            if decl.constrType():
                self.declaration(decl.aliasType().decl())
            for declarator in decl.declarators():
                name = self.header(declarator, "typedef")
                self.emit(name, "aliases", declarator_type(type_name(decl.aliasType()), declarator))
        elif isinstance(decl, idlast.Const):
            name = self.header(decl, "const")
            self.emit(name, "value", "%s = %s" % (type_name(decl.constType()), decl.value()))
        elif isinstance(decl, idlast.Union):
            name = self.header(decl, "union")
            self.emit(name, "discriminator", type_name(decl.switchType()))
            for index, case in enumerate(decl.cases()):
                labels = ", ".join("default" if label.default() else label_text(label.value())
                                   for label in case.labels())
                self.emit(name, "case %d" % index, "%s: %s %s" % (
                    labels, declarator_type(type_name(case.caseType()), case.declarator()),
                    case.declarator().identifier()))
        elif isinstance(decl, idlast.Native):
            self.header(decl, "native")
        elif isinstance(decl, (idlast.Forward, idlast.StructForward, idlast.UnionForward)):
            pass
        else:
            raise ValueError("unsupported declaration %r" % decl)

    def interface(self, decl):
        kind = "local interface" if decl.local() else "abstract interface" if decl.abstract() else "interface"
        name = self.header(decl, kind)
        self.emit(name, "inherits", ", ".join("::".join(base.scopedName()) for base in decl.inherits()) or "-")
        for inner in decl.contents():
            if isinstance(inner, idlast.Operation):
                params = ", ".join("%s %s" % (p.dirtext(), type_name(p.paramType())) for p in inner.parameters())
                raises = ", ".join("::".join(e.scopedName()) for e in inner.raises())
                self.emit(name, "operation " + inner.identifier(), "%s%s(%s)%s" % (
                    "oneway " if inner.oneway() else "", type_name(inner.returnType()), params,
                    " raises(%s)" % raises if raises else ""))
            elif isinstance(inner, idlast.Attribute):
                for identifier in inner.identifiers():
                    self.emit(name, "attribute " + identifier, "%s%s" % (
                        "readonly " if inner.readonly() else "", type_name(inner.attrType())))
            else:
                self.declaration(inner)


def run(tree, args):
    printer = Printer()
    for decl in tree.declarations():
        printer.declaration(decl)
    for line in sorted(printer.lines):
        print(line)
