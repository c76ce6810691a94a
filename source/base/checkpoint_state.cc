#include <deal.II/base/exceptions.h>

#include <mpm_otm/base/checkpoint_state.h>

namespace MpmOtm
{
  namespace
  {
    void
    missing(const std::string &name)
    {
      AssertThrow(false,
                  dealii::ExcMessage(
                    "The checkpoint holds no entry <" + name +
                    ">: it was written by another version of mpm-otm or for "
                    "another set-up. Start the run anew."));
    }
  } // namespace



  void
  CheckpointState::set_shared(const std::string         &name,
                              const std::vector<double> &values)
  {
    shared_entries[name] = values;
  }



  void
  CheckpointState::set_own(const std::string         &name,
                           const std::vector<double> &values)
  {
    own_entries[name] = values;
  }



  const std::vector<double> &
  CheckpointState::shared(const std::string &name) const
  {
    const auto entry = shared_entries.find(name);
    if (entry == shared_entries.end())
      missing(name);
    return entry->second;
  }



  std::vector<std::vector<double>>
  CheckpointState::parts(const std::string &name) const
  {
    std::vector<std::vector<double>> result;
    for (const auto &rank_entries : saved_parts)
      {
        const auto entry = rank_entries.find(name);
        if (entry == rank_entries.end())
          missing(name);
        result.push_back(entry->second);
      }
    return result;
  }



  std::vector<double>
  CheckpointState::share_of_sums(const std::string &name) const
  {
    const auto all = parts(name);
    if (all.empty())
      return {};
    if (same_n_ranks)
      return all[reader_rank];
    std::vector<double> sums(all[0].size(), 0.);
    if (reader_rank == 0)
      for (const auto &part : all)
        {
          AssertThrow(part.size() == sums.size(),
                      dealii::ExcMessage("The checkpoint entry <" + name +
                                         "> has parts of different sizes."));
          for (unsigned int i = 0; i < sums.size(); ++i)
            sums[i] += part[i];
        }
    return sums;
  }



  void
  CheckpointState::set_reader(const unsigned int rank,
                              const bool         same_number_of_ranks)
  {
    reader_rank  = rank;
    same_n_ranks = same_number_of_ranks;
  }
} // namespace MpmOtm
