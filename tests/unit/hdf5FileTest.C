// nmm::hdf5File: datasets, groups and attributes round trip; atomic
// creation; errors name the file and the dataset
#include "nmmSolid/io/hdf5File/hdf5File.H"
#include "nmmSolid/global/fatalError/fatalError.H"

#include "testTools.H"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

using nmm::hdf5File;

namespace
{

std::string errorOf(const std::function<void()>& call)
{
    try
    {
        call();
    }
    catch (const nmm::fatalError& e)
    {
        return e.what();
    }
    ADD_FAILURE() << "no error";
    return {};
}

} // End anonymous namespace


TEST(hdf5File, datasetsGroupsAndAttributesRoundTrip)
{
    nmm::test::tempDir dir("hdf5File");
    const auto file = dir.path / "state.h5";

    const std::vector<double> d{1.5, -0.0, std::numeric_limits<double>::denorm_min(),
        std::nan(""), 1e308};
    const std::vector<std::int32_t> i32{1, -2, 2147483647};
    const std::vector<std::int64_t> i64{-9000000000000000000LL, 0, 7};
    const hdf5File::array2D<double> a{2, 3, {1, 2, 3, 4, 5, 6}};
    const hdf5File::array2D<std::int32_t> b{3, 2, {1, 2, 3, 4, 5, 6}};
    {
        hdf5File out = hdf5File::create(file);
        out.write("a/b/c/d", d);
        out.write("ints", i32);
        out.write("a/longs", i64);
        out.write("tables/a", a);
        out.write("tables/b", b);
        out.write("empty", std::vector<double>{});
        out.createGroup("g/h");
        out.writeAttribute("/", "title", "restart state");
        out.writeAttribute("/", "empty", "");
        out.writeAttribute("a/b", "time", 1e-3);
        out.writeAttribute("tables/a", "index", std::int64_t(-42));
        out.writeAttribute("/", "title", "replaced");
        EXPECT_FALSE(std::filesystem::exists(file)) << "visible before commit";
        out.commit();
    }
    ASSERT_TRUE(std::filesystem::exists(file));
    EXPECT_FALSE(std::filesystem::exists(dir.path / ".state.h5.tmp"));

    const hdf5File in = hdf5File::openRead(file);
    const auto d2 = in.read<double>("a/b/c/d");
    ASSERT_EQ(d2.size(), d.size());
    EXPECT_EQ(0, std::memcmp(d.data(), d2.data(), d.size()*sizeof(double)));
    EXPECT_EQ(in.read<std::int32_t>("ints"), i32);
    EXPECT_EQ(in.read<std::int64_t>("a/longs"), i64);
    EXPECT_EQ(in.read<std::int64_t>("ints"), std::vector<std::int64_t>(i32.begin(), i32.end()));
    const auto a2 = in.read2D<double>("tables/a");
    EXPECT_EQ(a2.rows, 2u);
    EXPECT_EQ(a2.cols, 3u);
    EXPECT_EQ(a2.values, a.values);
    EXPECT_EQ(a2(1, 2), 6);
    EXPECT_EQ(in.read2D<std::int32_t>("tables/b", 2).values, b.values);
    EXPECT_TRUE(in.read<double>("empty").empty());
    EXPECT_TRUE(in.exists("g/h"));
    EXPECT_TRUE(in.exists("/a/b/c"));
    EXPECT_FALSE(in.exists("x/y/z"));
    EXPECT_EQ(in.members("tables"), (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(in.readStringAttribute("/", "title"), "replaced");
    EXPECT_EQ(in.readStringAttribute("/", "empty"), "");
    EXPECT_EQ(in.readDoubleAttribute("a/b", "time"), 1e-3);
    EXPECT_EQ(in.readIntAttribute("tables/a", "index"), -42);
}


TEST(hdf5File, anAttributeOfAnotherTypeIsAnErrorNamingIt)
{
    nmm::test::tempDir dir("hdf5File");
    const auto file = dir.path / "attributes.h5";
    {
        hdf5File out = hdf5File::create(file);
        out.writeAttribute("/", "title", "restart state");
        out.writeAttribute("/", "time", 0.5);
        out.writeAttribute("/", "count", std::int64_t(3));
        out.commit();
    }
    const hdf5File in = hdf5File::openRead(file);
    std::string msg = errorOf([&] { in.readDoubleAttribute("/", "title"); });
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("attribute \"title\" of \"/\" is not a number"), std::string::npos) << msg;
    msg = errorOf([&] { in.readIntAttribute("/", "time"); });
    EXPECT_NE(msg.find("attribute \"time\" of \"/\" is not an integer"), std::string::npos) << msg;
    msg = errorOf([&] { in.readStringAttribute("/", "count"); });
    EXPECT_NE(msg.find("attribute \"count\" of \"/\" is not a string"), std::string::npos) << msg;
    // An integer is a number
    EXPECT_EQ(in.readDoubleAttribute("/", "count"), 3.0);
}


TEST(hdf5File, notCommittedLeavesNothing)
{
    nmm::test::tempDir dir("hdf5File");
    const auto file = dir.path / "state.h5";
    {
        hdf5File out = hdf5File::create(file);
        out.write("x", std::vector<double>{1});
    }
    EXPECT_FALSE(std::filesystem::exists(file));
    EXPECT_TRUE(std::filesystem::is_empty(dir.path));
}


TEST(hdf5File, errorsNameFileAndDataset)
{
    nmm::test::tempDir dir("hdf5File");
    const auto file = dir.path / "state.h5";
    {
        hdf5File out = hdf5File::create(file);
        out.write("ints", std::vector<std::int32_t>{1, 2});
        out.write("longs", std::vector<std::int64_t>{1, 2});
        out.write("table", hdf5File::array2D<double>{1, 2, {1, 2}});
        out.commit();
    }
    const hdf5File in = hdf5File::openRead(file);
    std::string msg = errorOf([&] { in.read<double>("missing/x"); });
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("\"missing/x\""), std::string::npos) << msg;

    msg = errorOf([&] { in.read<double>("ints"); });
    EXPECT_NE(msg.find("does not hold double"), std::string::npos) << msg;
    msg = errorOf([&] { in.read<std::int32_t>("longs"); });
    EXPECT_NE(msg.find("does not hold int32"), std::string::npos) << msg;
    msg = errorOf([&] { in.read<double>("table"); });
    EXPECT_NE(msg.find("2 dimensions, expected 1"), std::string::npos) << msg;
    msg = errorOf([&] { in.read2D<double>("table", 3); });
    EXPECT_NE(msg.find("2 columns, expected 3"), std::string::npos) << msg;
    msg = errorOf([&] { in.readStringAttribute("/", "nope"); });
    EXPECT_NE(msg.find("no attribute \"nope\""), std::string::npos) << msg;

    msg = errorOf([&] { hdf5File::openRead(dir.path / "none.h5"); });
    EXPECT_NE(msg.find("cannot find file"), std::string::npos) << msg;

    // Not HDF5: no error stack on the terminal, one message
    const auto text = dir.write("text.h5", "not hdf5\n");
    testing::internal::CaptureStderr();
    msg = errorOf([&] { hdf5File::openRead(text); });
    const std::string printed = testing::internal::GetCapturedStderr();
    EXPECT_NE(msg.find("cannot open the file"), std::string::npos) << msg;
    EXPECT_EQ(printed, "");

    msg = errorOf([&] { hdf5File::create(dir.path / "no/such/dir/x.h5"); });
    EXPECT_NE(msg.find("cannot create the file"), std::string::npos) << msg;

    hdf5File ro = hdf5File::openRead(file);
    msg = errorOf([&] { ro.write("x", std::vector<double>{1}); });
    EXPECT_NE(msg.find("read-only"), std::string::npos) << msg;
}
