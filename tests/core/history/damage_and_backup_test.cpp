// A history file with a damaged page is read but never written (the save is
// refused naming the file and the restore), and every committed save leaves
// a whole rolling backup beside it that opens, passes integrity_check and
// holds that save.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/input_error.h"
#include "history/transaction.h"
#include "store_fixture.h"

namespace auv {
using test::hugin;
using test::water;

namespace {

TimePoint at(int day) { return TimePoint{} + std::chrono::hours(24 * (20000 + day)); }

// Overwrites one page in the middle of the main file with a byte pattern
// that no b-tree page has (as a bad disk sector or a stray write would).
void damagePage(const std::string& path, std::size_t page_size) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(0, std::ios::end);
  const auto size = static_cast<std::size_t>(f.tellg());
  ASSERT_GE(size, 4 * page_size);
  f.seekp(static_cast<std::streamoff>((size / page_size / 2) * page_size));
  std::string junk(page_size, '\0');
  for (std::size_t i = 0; i < page_size; ++i) junk[i] = static_cast<char>((i * 13 + 7) % 256);
  f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
}

}  // namespace

class HistoryDamageTest : public test::StoreTest {
 protected:
  // A history with enough records to span many pages, checkpointed into the main file.
  void fill() {
    HistoryStore s(db_path);
    s.addConfiguration(hugin("1-2-3", at(0)));
    for (int d = 1; d <= 300; ++d) s.addWaterCondition("1-2-3", water(at(d), 5.0 + d * 0.01, 35.0));
    s.database().exec("PRAGMA wal_checkpoint(TRUNCATE)", "checkpointing");
  }
};

TEST_F(HistoryDamageTest, EverySaveRefreshesAWholeBackup) {
  fill();
  const std::string bak = db_path + ".bak";
  ASSERT_TRUE(std::filesystem::exists(bak));
  HistoryStore backup(bak);
  EXPECT_EQ(backup.integrityCheck(), "ok");
  ASSERT_TRUE(backup.configuration("1-2-3"));
  const auto w = backup.latestWater("1-2-3", at(400));
  ASSERT_TRUE(w && w->temperature_degC);
  EXPECT_DOUBLE_EQ(*w->temperature_degC, 5.0 + 300 * 0.01);  // the last save is in the backup
}

TEST_F(HistoryDamageTest, DamagedFileIsReadButNeverWrittenAndTheBackupRestores) {
  fill();
  const auto page = static_cast<std::size_t>(HistoryStore(db_path).database().queryInt("PRAGMA page_size"));
  damagePage(db_path, page);
  const std::string before = test::readAll(db_path);

  HistoryStore s(db_path);
  EXPECT_FALSE(s.damage().empty());
  EXPECT_NE(s.integrityCheck(), "ok");
  try {
    s.addWaterCondition("1-2-3", water(at(500), 9.0, 35.0));
    FAIL() << "a damaged history must not be written";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(db_path), std::string::npos) << m;
    EXPECT_NE(m.find("is damaged"), std::string::npos) << m;
    EXPECT_NE(m.find("restore the automatic backup"), std::string::npos) << m;
    EXPECT_NE(m.find(db_path + ".bak"), std::string::npos) << m;
  }
  EXPECT_EQ(test::readAll(db_path), before);  // untouched

  // The restore the message describes gives back every committed save.
  std::filesystem::copy_file(db_path + ".bak", db_path, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::remove(db_path + "-wal");
  std::filesystem::remove(db_path + "-shm");
  HistoryStore restored(db_path);
  EXPECT_TRUE(restored.damage().empty());
  const auto w = restored.latestWater("1-2-3", at(400));
  ASSERT_TRUE(w && w->temperature_degC);
  EXPECT_DOUBLE_EQ(*w->temperature_degC, 5.0 + 300 * 0.01);  // the last committed save is back
  EXPECT_NO_THROW(restored.addWaterCondition("1-2-3", water(at(500), 9.0, 35.0)));
}

}  // namespace auv
