#pragma once
// The known mistakes as a student's copy of the kit ships them (issue 40): beside a lab's golden images,
// grader/golden/<lab>/mistakes.json (each mistake's text, its TODO, the part of the sheet that teaches it, the public
// cases its picture fails) and mistakes.png (each mistake's picture of each case it fails, as a signature:
// common/image/picture_signature.h). No edit, no code, no hidden case: what a student sees of a mistake is its
// picture and the idea it missed. Written by `gsv-grade --update-mistakes` from the instructor's lists
// (tests/mutants/<lab>.json); read by the self-check, the browser page's self-check and `compare`.
#include "common/image/comparison_image.h"
#include "common/image/picture_signature.h"

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gsv {

// A TODO's starter code as the starter has it, per file: blocks of lines (each trimmed), each ending with the line that
// follows it, each after the lines between the comment naming the TODO and the block. Public: it is the starter's.
using StarterBlocks = std::map<std::string, std::vector<std::vector<std::string>>>;

struct ShippedMistake {
    std::string id;                // "L01-T1 a": no name that says what the edit was
    std::string todo, says, sheet;
    bool not_started = false;      // the TODO left as the starter has it
    StarterBlocks starter;         // not started: the starter's code, which tells it from a mistake that draws the same
    std::set<std::string> fails;   // the public cases its picture (or a render that failed) fails against the goldens
};

struct ShippedPicture {
    std::size_t mistake = 0;  // in KnownMistakePictures::mistakes
    PictureSignature signature;
};

struct KnownMistakePictures {
    std::string lab, lab_dir;  // lab_dir: its folder in labs/
    int block = 0;
    std::string inputs;  // the fingerprint of what the pictures were made from (mistake_pictures_inputs)
    std::vector<ShippedMistake> mistakes;
    std::map<std::string, std::vector<ShippedPicture>> cases;  // public case -> the pictures of the mistakes that fail it
    bool empty() const { return mistakes.empty(); }
};

std::filesystem::path known_mistakes_file(const std::filesystem::path& kit_root, const std::string& lab);

// The lab's shipped mistakes; none (empty) where the kit has no grader/golden/<lab>/mistakes.json. Throws gsv::Error
// naming the file and what is wrong where it is malformed or its picture file is missing or does not fit.
KnownMistakePictures read_known_mistake_pictures(const std::filesystem::path& kit_root, const std::string& lab);
// Writes mistakes.json and mistakes.png (identical signatures stored once).
void write_known_mistake_pictures(const std::filesystem::path& kit_root, const KnownMistakePictures& pictures);

// What the shipped pictures are made from, in the instructor's kit: the lab's mistake list, case file, goldens and
// reference solution. A shipped file whose `inputs` differ is stale (made before one of them changed).
std::string mistake_pictures_inputs(const std::filesystem::path& kit_root, const std::string& lab, const std::string& lab_dir);

// The mistakes whose shipped picture of `case_name` `picture` matches (signature_matches against the golden's
// signature), nearest first.
std::vector<std::size_t> matching_mistakes(const KnownMistakePictures& pictures, const std::string& case_name, const Image& picture,
                                           const Image& golden);

// compare's fourth view (common/image/comparison_image.h): the nearest matching mistake's picture of the case, scaled
// to width x height, and what it says; none where no shipped mistake matches.
std::optional<MistakePanel> known_mistake_panel(const KnownMistakePictures& pictures, const std::string& case_name,
                                                const Image& picture, const Image& golden);

// Whether the student's copy of the lab (`student_folder`) still holds the starter's code of `todo`, right after a
// comment that names it (blank lines and surrounding white space aside).
bool holds_starter(const std::filesystem::path& student_folder, const std::string& todo, const StarterBlocks& blocks);

}  // namespace gsv
