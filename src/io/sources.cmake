# included from src/CMakeLists.txt; paths are relative to src/

# flexrock::io: record files (PEER .AT2, single-column, time/acceleration text and CSV)
add_library(flexrock_io io/records.cpp)
add_library(flexrock::io ALIAS flexrock_io)
target_link_libraries(flexrock_io PUBLIC flexrock::core PRIVATE flexrock_warnings)
flexrock_apply_sanitizers(flexrock_io)
