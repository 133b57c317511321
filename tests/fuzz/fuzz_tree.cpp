// libFuzzer target: the variable tree as peers and layouts drive it. Each
// input is a list of operations on one tree and its QML model:
//   0 ingest [u16 length][packet]   a packet decoded with the shipped definitions
//   1 name   [u16 id][u8 length][UTF-8]   a system's configured name
//   2 find   [u8 length][UTF-8]     a path, as a layout or script names one
//   3 node   [u16 index]            reads a node every way a view does
//   4 model                         the model syncs and is read, as a view would
//   5 forget [u16 id]               a system falls silent and is forgotten
// Beyond "no crash, no sanitizer report", it checks that every node's path
// leads back to a node of that same path, and that every packet that
// decodes lands in the tree under its system and type.
#include "FuzzApplication.h"
#include "Paths.h"
#include "messages/Codec.h"
#include "qmlmodels/VariableTreeModel.h"
#include "tree/VariableTree.h"


#include <cstdio>
#include <cstdlib>

using namespace neptus;

namespace {

const msg::Codec &codec()
{
    static const msg::Codec codec([] {
        auto schema = msg::Schema::load(msg::Schema::filesIn(test::msgdefsDirectory()));
        if (!schema) {
            std::fprintf(stderr, "fuzz_tree: %s\n", qPrintable(schema.error().toString()));
            std::abort();
        }
        return *schema;
    }());
    return codec;
}

[[noreturn]] void fail(const char *what, const QString &detail)
{
    std::fprintf(stderr, "fuzz_tree: %s: %s\n", what, qPrintable(detail));
    std::abort();
}

void checkPath(const tree::VariableTree &tree, tree::NodeId node)
{
    if (node != tree.root() && tree.systemOf(node) == 0xFFFF)
        return; // a forgotten system's node (or a free id): no path leads there
    const QString path = tree.path(node);
    const tree::NodeId found = tree.find(path);
    if (found == tree::noNode)
        fail("a node's path finds nothing", path);
    if (tree.path(found) != path)
        fail("a node's path finds a node of another path", path + QStringLiteral(" -> ") + tree.path(found));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    test::ensureFuzzApplication();

    tree::VariableTree tree;
    tree::VariableTreeModel model(&tree);
    size_t at = 0;
    const auto take = [&](size_t n) -> const uint8_t * {
        if (at + n > size)
            return nullptr;
        const uint8_t *p = data + at;
        at += n;
        return p;
    };
    const auto text = [&](size_t n) {
        const uint8_t *p = take(n);
        return p ? QString::fromUtf8(reinterpret_cast<const char *>(p), static_cast<qsizetype>(n)) : QString();
    };
    while (const uint8_t *op = take(1)) {
        switch (*op % 6) {
        case 0: {
            const uint8_t *l = take(2);
            if (!l)
                break;
            const size_t length = std::min<size_t>((size_t(l[0]) << 8) | l[1], size - at);
            const QByteArrayView packet(data + at, static_cast<qsizetype>(length));
            at += length;
            const auto message = codec().decode(packet);
            if (!message)
                break;
            tree.ingest(*message);
            if (tree.find(tree.systemName(message->header.src) + u'/' + message->abbrev()) == tree::noNode)
                fail("a decoded packet is not in the tree", message->abbrev());
            break;
        }
        case 1: {
            const uint8_t *id = take(2);
            const uint8_t *l = take(1);
            if (id && l)
                tree.setSystemName(quint16((id[0] << 8) | id[1]), text(*l));
            break;
        }
        case 2: {
            const uint8_t *l = take(1);
            if (!l)
                break;
            const tree::NodeId node = tree.find(text(*l));
            if (node != tree::noNode)
                checkPath(tree, node);
            break;
        }
        case 3: {
            const uint8_t *i = take(2);
            if (!i || tree.nodeCapacity() == 0)
                break;
            const tree::NodeId node = ((i[0] << 8) | i[1]) % tree.nodeCapacity();
            checkPath(tree, node);
            tree.snapshot(node);
            tree.childNames(tree.path(node));
            tree.entityLabels(tree.systemOf(node));
            break;
        }
        case 4:
            model.sync();
            for (int row = 0; row < model.rowCount({}); ++row) {
                const QModelIndex system = model.index(row, 0, {});
                model.data(system, Qt::DisplayRole);
                if (model.rowCount(system) > 0)
                    model.data(model.index(0, 1, system), Qt::DisplayRole);
            }
            break;
        case 5: {
            const uint8_t *id = take(2);
            if (!id)
                break;
            const quint16 system = quint16((id[0] << 8) | id[1]) % 8; // the ids a short input sends from
            const QString name = tree.systemName(system);
            tree.forget(system);
            if (tree.find(name) != tree::noNode && !tree.systemId(name))
                fail("a forgotten system is still found", name);
            break;
        }
        }
    }
    for (tree::NodeId node = 0; node < std::min(tree.nodeCapacity(), 4000); ++node)
        checkPath(tree, node);
    return 0;
}
