#include "Schemas.h"
#include "Fixtures.h"
#include "messages/Schema.h"

#include <gtest/gtest.h>

using namespace neptus::msg;

namespace {

// A small definition document around the given message elements.
QByteArray defs(const char *body, const char *extra = "")
{
    return QByteArray("<?xml version=\"1.0\"?>\n<messages name=\"Test\" version=\"1\">\n") + extra + body
           + "\n</messages>\n";
}

std::expected<std::shared_ptr<const Schema>, neptus::xml::XmlError> load(const QByteArray &doc)
{
    return Schema::fromData({{QStringLiteral("test.xml"), doc}});
}

} // namespace

TEST(Schema, LoadsTheWholeImcDefinition)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    auto loaded = Schema::load({path});
    ASSERT_TRUE(loaded) << loaded.error().toString().toStdString();
    const Schema &schema = **loaded;
    EXPECT_EQ(schema.messages().size(), 349u);
    EXPECT_EQ(schema.fieldCount(), 1552);
    EXPECT_EQ(schema.enumerationCount(), 7);
    EXPECT_EQ(schema.bitfieldCount(), 2);
    EXPECT_EQ(schema.groups().size(), 4u);
    EXPECT_EQ(schema.syncNumber(), 0xFE54);
    EXPECT_EQ(schema.name(), QStringLiteral("IMC"));
    EXPECT_EQ(schema.version(), QStringLiteral("5.4.31"));
    EXPECT_EQ(schema.digest().size(), 32);
}

TEST(Schema, ImcMessagesHaveTheirFieldsInOrder)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    const auto schema = neptus::test::imcSchema();
    ASSERT_TRUE(schema);
    const MessageDef *state = schema->byId(350);
    ASSERT_TRUE(state);
    EXPECT_EQ(state->abbrev, QStringLiteral("EstimatedState"));
    EXPECT_EQ(schema->byAbbrev(u"EstimatedState"), state);
    ASSERT_EQ(state->fields.size(), 20u);
    EXPECT_EQ(state->fields[0].abbrev, QStringLiteral("lat"));
    EXPECT_EQ(state->fields[0].type, FieldType::Fp64);
    EXPECT_EQ(state->fields[0].unit, QStringLiteral("rad"));
    EXPECT_EQ(state->fields[19].abbrev, QStringLiteral("alt"));
    EXPECT_EQ(state->fixedPayloadSize, 2 * 8 + 18 * 4);

    // Inline enumeration with a prefix.
    const FieldDef *entityState = schema->byAbbrev(u"EntityState")->field(u"state");
    ASSERT_TRUE(entityState && entityState->enumeration);
    EXPECT_EQ(entityState->enumeration->prefix, QStringLiteral("ESTA"));
    EXPECT_EQ(entityState->enumeration->format(1), QStringLiteral("NORMAL"));
    EXPECT_EQ(entityState->enumeration->parse(u"FAILURE"), 4);

    // Global enumeration by enum-def, global bitfield by bitfield-def.
    const FieldDef *sysType = schema->byAbbrev(u"Announce")->field(u"sys_type");
    ASSERT_TRUE(sysType && sysType->enumeration);
    EXPECT_EQ(sysType->enumeration, schema->enumeration(u"SystemType"));
    EXPECT_EQ(sysType->enumeration->format(2), QStringLiteral("UUV"));
    const FieldDef *loops = schema->byAbbrev(u"ControlLoops")->field(u"mask");
    ASSERT_TRUE(loops && loops->enumeration && loops->enumeration->bitfield);
    EXPECT_EQ(loops->enumeration->format(0x8 | 0x1), QStringLiteral("PATH|DEPTH"));
    EXPECT_EQ(loops->enumeration->parse(u"PATH|DEPTH"), 0x9);

    // Message fields restricted to a group.
    const FieldDef *data = schema->byAbbrev(u"PlanManeuver")->field(u"data");
    ASSERT_TRUE(data);
    EXPECT_EQ(data->type, FieldType::Message);
    EXPECT_EQ(data->messageType, QStringLiteral("Maneuver"));
    EXPECT_TRUE(data->allowedIds.contains(schema->byAbbrev(u"Goto")->id));
    EXPECT_FALSE(data->allowedIds.contains(350));
    const MessageGroup *maneuvers = schema->group(u"Maneuver");
    ASSERT_TRUE(maneuvers);
    EXPECT_TRUE(maneuvers->members.contains(QStringLiteral("Goto")));
}

TEST(Schema, CombinesFilesWithUserMessages)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray standard = file.readAll();
    const QByteArray mine = defs(R"(
  <message-groups>
    <message-group name="Maneuver" abbrev="Maneuver"><message-type abbrev="Spiral"/></message-group>
  </message-groups>
  <message id="1001" name="Spiral" abbrev="Spiral">
    <field name="Turns" abbrev="turns" type="uint8_t"/>
    <field name="Mode" abbrev="mode" type="uint8_t" unit="Enumerated" enum-def="Boolean"/>
  </message>)");
    auto loaded = Schema::fromData({{QStringLiteral("IMC.xml"), standard}, {QStringLiteral("mine.xml"), mine}});
    ASSERT_TRUE(loaded) << loaded.error().toString().toStdString();
    const Schema &schema = **loaded;
    EXPECT_EQ(schema.messages().size(), 350u);
    ASSERT_TRUE(schema.byId(1001));
    EXPECT_EQ(schema.byId(1001)->field(u"mode")->enumeration, schema.enumeration(u"Boolean"));
    // The user's maneuver joined the standard group, so plans may carry it.
    EXPECT_TRUE(schema.byAbbrev(u"PlanManeuver")->field(u"data")->allowedIds.contains(1001));
    EXPECT_NE(schema.digest(), neptus::test::imcSchema()->digest());
}

TEST(Schema, DuplicateIdsAndNamesAcrossFilesAreErrors)
{
    NEPTUS_REQUIRE_FIXTURE(path, "imc/IMC.xml");
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    const QByteArray standard = file.readAll();
    auto loaded = Schema::fromData({{QStringLiteral("IMC.xml"), standard},
                                    {QStringLiteral("mine.xml"), defs("<message id=\"350\" name=\"X\" abbrev=\"MyState\"/>")}});
    ASSERT_FALSE(loaded);
    const QString error = loaded.error().toString();
    EXPECT_TRUE(error.startsWith(QStringLiteral("mine.xml:3:"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("id 350"))) << error.toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("EstimatedState at IMC.xml:"))) << error.toStdString();

    loaded = Schema::fromData({{QStringLiteral("IMC.xml"), standard},
                               {QStringLiteral("mine.xml"), defs("<message id=\"1200\" name=\"X\" abbrev=\"Goto\"/>")}});
    ASSERT_FALSE(loaded);
    EXPECT_TRUE(loaded.error().toString().contains(QStringLiteral("Goto"))) << loaded.error().toString().toStdString();
}

TEST(Schema, NamesWhatIsWrongInADefinition)
{
    struct Case
    {
        const char *body;
        const char *expected;
    };
    const Case cases[] = {
        {"<message id=\"1\" name=\"A\" abbrev=\"A\"><field abbrev=\"x\" type=\"float\"/></message>", "unknown type 'float'"},
        {"<message id=\"x\" name=\"A\" abbrev=\"A\"/>", "message id 'x'"},
        {"<message id=\"65535\" name=\"A\" abbrev=\"A\"/>", "0 to 65534"},
        {"<message id=\"1\" name=\"A\" abbrev=\"A b\"/>", "identifier"},
        {"<message id=\"1\" abbrev=\"A\"><field abbrev=\"x\" type=\"uint8_t\"/><field abbrev=\"x\" type=\"uint8_t\"/></message>",
         "two fields named x"},
        {"<message id=\"1\" abbrev=\"A\"><field abbrev=\"x\" type=\"uint8_t\" enum-def=\"Nope\"/></message>",
         "enum-def 'Nope'"},
        {"<message id=\"1\" abbrev=\"A\"><field abbrev=\"x\" type=\"fp32_t\" unit=\"Enumerated\"><value id=\"1\" abbrev=\"ONE\"/></field></message>",
         "integer type"},
        {"<message id=\"1\" abbrev=\"A\"><field abbrev=\"x\" type=\"uint8_t\" unit=\"Enumerated\"><value id=\"300\" abbrev=\"BIG\"/></field></message>",
         "does not fit"},
        {"<message id=\"1\" abbrev=\"A\"><field abbrev=\"m\" type=\"message\" message-type=\"Nothing\"/></message>",
         "names no message or message group"},
        {"<message-groups><message-group abbrev=\"G\" name=\"G\"><message-type abbrev=\"Ghost\"/></message-group></message-groups>",
         "lists Ghost"},
        {"<header><field abbrev=\"sync\" type=\"uint16_t\" value=\"0xFE54\"/></header><footer><field abbrev=\"crc16\" type=\"uint16_t\"/></footer>",
         "lacks field mgid"},
    };
    for (const Case &c : cases) {
        const auto loaded = load(defs(c.body));
        ASSERT_FALSE(loaded) << c.body;
        const QString error = loaded.error().toString();
        EXPECT_TRUE(error.startsWith(QStringLiteral("test.xml:"))) << error.toStdString();
        EXPECT_TRUE(error.contains(QString::fromUtf8(c.expected))) << "expected '" << c.expected << "' in: " << error.toStdString();
    }
    const auto notDefs = load("<html/>");
    ASSERT_FALSE(notDefs);
    EXPECT_TRUE(notDefs.error().message.contains(QStringLiteral("<messages>")));
}

TEST(Schema, DigestFollowsTheWireFormatOnly)
{
    const char *a = "<message id=\"1\" abbrev=\"A\"><description>one</description><field abbrev=\"x\" type=\"uint8_t\"/></message>";
    const char *sameButComments = "<!-- changed --><message id=\"1\" abbrev=\"A\" name=\"Another name\">\n"
                                  "<description>two</description>\n<field name=\"X!\" abbrev=\"x\" type=\"uint8_t\"/></message>";
    const char *otherType = "<message id=\"1\" abbrev=\"A\"><field abbrev=\"x\" type=\"uint16_t\"/></message>";
    const auto first = load(defs(a)), second = load(defs(sameButComments)), third = load(defs(otherType));
    ASSERT_TRUE(first && second && third);
    EXPECT_EQ((*first)->digest(), (*second)->digest());
    EXPECT_NE((*first)->digest(), (*third)->digest());
}
